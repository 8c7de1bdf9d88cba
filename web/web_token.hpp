#pragma once
// The dashboard's login token (docs/dashboard.md): under authentication a browser proves it holds a
// key of the server's key file (message_auth.hpp) without the secret ever reaching the browser:
//   token = KEY_ID "." EXPIRY "." hex(HMAC-SHA256(secret, "cyclopt-web " KEY_ID " " EXPIRY))
// EXPIRY in Unix seconds. `cyclopt-web token --key-file FILE` makes one from the user's own key
// file; cyclopt-web checks it against the server's key file and acts with that key (reads as the
// server's auth_reads allow, cancels signed with it, so the server's owner rule decides).

#include "message_auth.hpp"

#include <cstdint>
#include <string>

namespace cyclopt::web {

std::string make_token(const wire::AuthKey& key, std::int64_t expires_unix);

// The key the token was made with, or nullptr with `problem` set ("malformed token", "unknown
// key 'x'", "expired token", "bad token").
const wire::AuthKey* check_token(const wire::KeyRing& keys, const std::string& token, std::int64_t now_unix,
                                 std::string& problem);

}  // namespace cyclopt::web
