#pragma once
// The wire layout of an LCM message type: its fields in encoding order. lcm-gen's encoding is an
// 8-byte big-endian type fingerprint followed by every field big-endian; a string is an int32
// length that counts a terminating NUL, then the bytes and that NUL. LcmLayout<T> is generated
// from proto/lcm/*.lcm by lcm_layouts.cmake (header cyclopt_lcm_layouts.hpp).

namespace cyclopt::wire {

enum class FieldKind { string, int64, int32, float64, boolean };

struct Field {
  FieldKind kind;
  const char* name;
};

template <class T>
struct LcmLayout;

}  // namespace cyclopt::wire
