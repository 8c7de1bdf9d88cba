#include "result_source.hpp"

#include "message_auth.hpp"

#include <cstdio>
#include <cstdlib>

namespace cyclopt::client {

storage::QueryPage ResultSource::fetch(storage::QueryRequest r) {
  r.limit = 1000;
  if (reads_database()) {
    storage::ResultReader& store = local();
    storage::QueryPage all;
    while (true) {
      storage::QueryPage page = storage::run_query(store, r);
      all.total = page.total;
      for (auto& row : page.rows) all.rows.push_back(std::move(row));
      r.offset += static_cast<int>(page.rows.size());
      if (page.rows.empty() || r.offset >= page.total) return all;
    }
  }
  r.limit = 1 << 30;
  auto page = remote().query(r, options_.timeout);
  if (!page) {
    char text[96];
    std::snprintf(text, sizeof text, "no answer from cycloptd within %g s", options_.timeout);
    throw NoAnswer(text);
  }
  return *page;
}

storage::ResultReader& ResultSource::local() {
  if (!store_) store_.emplace(options_.database);
  return *store_;
}

ServiceClient& ResultSource::remote() {
  if (!client_) {
    const std::string url = wire::resolved_lcm_url(options_.lcm_url);
    lcm_.emplace(url);
    if (!lcm_->good()) throw std::runtime_error("cannot open LCM at '" + url + "'");
    std::string key_file = options_.key_file;
    if (const char* env = std::getenv("CYCLOPT_KEY_FILE"); key_file.empty() && env) key_file = env;
    std::optional<wire::AuthKey> key;
    if (!key_file.empty()) key = wire::read_key_file(key_file).keys.front();
    client_.emplace(*lcm_, url, key);
  }
  return *client_;
}

}  // namespace cyclopt::client
