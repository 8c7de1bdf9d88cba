#include "wire_check.hpp"

namespace cyclopt::wire {

namespace {

std::uint64_t big_endian(std::span<const std::uint8_t> b) {
  std::uint64_t v = 0;
  for (std::uint8_t byte : b) v = v << 8 | byte;
  return v;
}

std::size_t field_bytes(FieldKind k) {
  switch (k) {
    case FieldKind::int64:
    case FieldKind::float64: return 8;
    case FieldKind::int32: return 4;
    case FieldKind::boolean: return 1;
    case FieldKind::string: return 4;  // its length field
  }
  return 0;
}

}  // namespace

bool is_utf8(std::string_view text) {
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned char c = s[i];
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len;
    std::uint32_t cp, min;
    if ((c & 0xe0) == 0xc0) len = 2, cp = c & 0x1f, min = 0x80;
    else if ((c & 0xf0) == 0xe0) len = 3, cp = c & 0x0f, min = 0x800;
    else if ((c & 0xf8) == 0xf0) len = 4, cp = c & 0x07, min = 0x10000;
    else return false;
    if (n - i < len) return false;
    for (std::size_t k = 1; k < len; ++k) {
      if ((s[i + k] & 0xc0) != 0x80) return false;
      cp = cp << 6 | (s[i + k] & 0x3f);
    }
    if (cp < min || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return false;
    i += len;
  }
  return true;
}

std::string encoding_problem(std::span<const std::uint8_t> bytes, std::int64_t fingerprint,
                             std::span<const Field> fields, const char* type_name) {
  const std::string type = type_name;
  if (bytes.size() < 8) return "not a " + type + ": " + std::to_string(bytes.size()) + " bytes, shorter than a fingerprint";
  if (bytes.size() > (std::size_t{1} << 30)) return "not a " + type + ": oversize";
  if (static_cast<std::int64_t>(big_endian(bytes.first(8))) != fingerprint)
    return "not a " + type + " (wrong type fingerprint)";
  std::size_t pos = 8;
  for (const Field& f : fields) {
    const std::string where = type + "." + f.name + " at byte " + std::to_string(pos);
    const std::size_t need = field_bytes(f.kind);
    if (bytes.size() - pos < need) return where + ": truncated";
    const auto raw = bytes.subspan(pos, need);
    pos += need;
    if (f.kind == FieldKind::boolean && raw[0] > 1) return where + ": boolean must be 0 or 1, got " + std::to_string(raw[0]);
    if (f.kind != FieldKind::string) continue;
    const auto len = static_cast<std::int32_t>(static_cast<std::uint32_t>(big_endian(raw)));
    const std::size_t left = bytes.size() - pos;
    if (len < 1) return where + ": string length " + std::to_string(len) + " (must be at least 1, counting its NUL)";
    if (static_cast<std::size_t>(len) > left)
      return where + ": string length " + std::to_string(len) + " exceeds the " + std::to_string(left) + " bytes left";
    if (static_cast<std::size_t>(len) - 1 > kMaxStringBytes)
      return where + ": string of " + std::to_string(len - 1) + " bytes, at most " + std::to_string(kMaxStringBytes);
    const std::string_view text(reinterpret_cast<const char*>(bytes.data() + pos), static_cast<std::size_t>(len) - 1);
    if (bytes[pos + static_cast<std::size_t>(len) - 1] != 0) return where + ": string not NUL-terminated";
    if (text.find('\0') != std::string_view::npos) return where + ": string contains a NUL byte";
    if (!is_utf8(text)) return where + ": string is not valid UTF-8";
    pos += static_cast<std::size_t>(len);
  }
  if (pos != bytes.size())
    return type + ": " + std::to_string(bytes.size() - pos) + " bytes after the last field (" + std::to_string(pos) +
           " expected)";
  return "";
}

}  // namespace cyclopt::wire
