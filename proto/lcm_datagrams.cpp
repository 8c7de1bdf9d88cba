#include "lcm_datagrams.hpp"

#include <algorithm>

namespace cyclopt::wire {

namespace {

std::uint32_t u32(std::span<const std::uint8_t> d, std::size_t at) {
  return std::uint32_t{d[at]} << 24 | std::uint32_t{d[at + 1]} << 16 | std::uint32_t{d[at + 2]} << 8 | d[at + 3];
}
std::uint16_t u16(std::span<const std::uint8_t> d, std::size_t at) {
  return static_cast<std::uint16_t>(d[at] << 8 | d[at + 1]);
}

}  // namespace

std::optional<std::string> channel_at(std::span<const std::uint8_t> bytes) {
  std::string channel;
  for (std::uint8_t c : bytes.first(std::min(bytes.size(), kMaxChannelBytes + 1))) {
    if (c == 0) {
      if (channel.empty()) return std::nullopt;
      return channel;
    }
    if (c < 0x21 || c > 0x7e) return std::nullopt;
    channel += static_cast<char>(c);
  }
  return std::nullopt;  // no NUL within 64 bytes
}

void DatagramAssembler::drop(std::map<std::uint64_t, Assembly>::iterator it) {
  pending_bytes_ -= it->second.data.size();
  pending_.erase(it);
  ++counters_.dropped_assemblies;
}

void DatagramAssembler::expire(double now) {
  for (auto it = pending_.begin(); it != pending_.end();) {
    auto next = std::next(it);
    if (now - it->second.last_seen > limits_.stale_seconds) drop(it);
    it = next;
  }
}

std::optional<LcmMessage> DatagramAssembler::feed(std::span<const std::uint8_t> d, std::uint64_t sender, double now) {
  ++counters_.datagrams;
  if (!pending_.empty()) expire(now);
  if (d.size() < 8) {
    ++counters_.malformed;
    return std::nullopt;
  }
  const std::uint32_t magic = u32(d, 0);
  if (magic == kMagicFragment) return feed_fragment(d, sender, now);
  if (magic != kMagicShort) {
    ++counters_.malformed;
    return std::nullopt;
  }
  const auto rest = d.subspan(8);
  const auto channel = channel_at(rest);
  if (!channel) {
    ++counters_.malformed;
    return std::nullopt;
  }
  const auto payload = rest.subspan(channel->size() + 1);
  ++counters_.messages;
  return LcmMessage{*channel, {payload.begin(), payload.end()}, ""};
}

std::optional<LcmMessage> DatagramAssembler::feed_fragment(std::span<const std::uint8_t> d, std::uint64_t sender,
                                                           double now) {
  if (d.size() < kFragmentHeaderBytes) {
    ++counters_.malformed;
    return std::nullopt;
  }
  const std::uint32_t seqno = u32(d, 4);
  const std::uint64_t size = u32(d, 8);
  const std::uint64_t offset = u32(d, 12);
  const std::uint16_t number = u16(d, 16);
  const std::uint16_t count = u16(d, 18);
  auto body = d.subspan(kFragmentHeaderBytes);
  auto it = pending_.find(sender);
  // A fragment of another message from this sender supersedes the one in assembly (liblcm too).
  if (it != pending_.end() && (it->second.seqno != seqno || it->second.data.size() != size)) {
    drop(it);
    it = pending_.end();
  }
  if (size == 0 || count == 0 || number >= count || count > size) {
    ++counters_.malformed;
    return std::nullopt;
  }
  if (size > limits_.max_message_bytes) {
    ++counters_.oversize;
    return std::nullopt;
  }
  if (it == pending_.end()) {
    if (number != 0) return std::nullopt;  // its first fragment was lost: nothing to assemble
    const auto channel = channel_at(body);
    if (!channel) {
      ++counters_.malformed;
      return std::nullopt;
    }
    body = body.subspan(channel->size() + 1);
    while (!pending_.empty() && pending_bytes_ + size > limits_.max_pending_bytes) {
      drop(std::min_element(pending_.begin(), pending_.end(),
                            [](const auto& a, const auto& b) { return a.second.last_seen < b.second.last_seen; }));
    }
    Assembly a;
    a.channel = *channel;
    a.seqno = seqno;
    a.data.assign(size, 0);
    a.have.assign(count, false);
    a.fragments_left = count;
    pending_bytes_ += size;
    it = pending_.emplace(sender, std::move(a)).first;
  } else if (number >= it->second.have.size()) {
    ++counters_.malformed;  // the fragment count changed
    drop(it);
    return std::nullopt;
  } else if (it->second.have[number]) {
    return std::nullopt;  // a repeated fragment
  }
  Assembly& a = it->second;
  if (offset + body.size() > a.data.size()) {
    ++counters_.malformed;
    drop(it);
    return std::nullopt;
  }
  a.have[number] = true;
  std::copy(body.begin(), body.end(), a.data.begin() + static_cast<std::ptrdiff_t>(offset));
  a.last_seen = now;
  if (--a.fragments_left > 0) return std::nullopt;
  LcmMessage m{std::move(a.channel), std::move(a.data), ""};
  pending_bytes_ -= m.payload.size();
  pending_.erase(it);
  ++counters_.messages;
  return m;
}

}  // namespace cyclopt::wire
