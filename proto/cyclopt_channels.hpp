#pragma once
// LCM channel names of the cyclopt service and the size limits both sides enforce.
// Types: proto/lcm/*.lcm (generated C++ in namespace cyclopt_lcm).

#include <cstddef>

namespace cyclopt::channels {

inline constexpr const char* kSubmit = "CYCLOPT_SUBMIT";          // job_submit_t   client -> server
inline constexpr const char* kCancel = "CYCLOPT_CANCEL";          // job_cancel_t   client -> server
inline constexpr const char* kQuery = "CYCLOPT_QUERY";            // query_request_t client -> server
inline constexpr const char* kAck = "CYCLOPT_ACK";                // job_ack_t      server -> clients
inline constexpr const char* kProgress = "CYCLOPT_PROGRESS";      // job_progress_t server -> clients
inline constexpr const char* kDone = "CYCLOPT_DONE";              // job_done_t     server -> clients
inline constexpr const char* kQueryReply = "CYCLOPT_QUERY_REPLY";  // query_reply_t  server -> clients

// Regex for lcm-logger / lcm-spy: every channel of the service.
inline constexpr const char* kAllChannels = "CYCLOPT_.*";

inline constexpr std::size_t kMaxSpecBytes = 16 * 1024;        // job_submit_t::spec_json
inline constexpr std::size_t kMaxRequestIdBytes = 64;
inline constexpr std::size_t kMaxQueryReplyRowBytes = 48 * 1024;  // query_reply_t::rows_json
inline constexpr int kMaxQueryLimit = 1000;

// Under authentication, the server's whole answer to a request whose signature it does not accept
// (unsigned, unknown key, wrong secret, stale or replayed): a job_ack_t on kAck, unsigned (the
// server cannot sign for a key it does not know), with field "signature", this problem and
// nothing else, whatever the request's channel. docs/operating-the-service.md says why it is harmless.
inline constexpr const char* kSignatureRejected = "signature rejected (unknown key or wrong secret)";

}  // namespace cyclopt::channels
