// cyclopt-log-channels: integration-test helper. Prints "CHANNEL COUNT" for every channel in an
// LCM log file (as written by lcm-logger), read event by event.
#include <lcm/lcm-cpp.hpp>

#include <cstdio>
#include <map>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cyclopt-log-channels FILE.lcmlog\n");
    return 1;
  }
  lcm::LogFile log(argv[1], "r");
  if (!log.good()) {
    std::fprintf(stderr, "cannot read %s\n", argv[1]);
    return 1;
  }
  std::map<std::string, long> counts;
  while (const lcm::LogEvent* e = log.readNextEvent()) ++counts[e->channel];
  for (const auto& [channel, n] : counts) std::printf("%s %ld\n", channel.c_str(), n);
  return 0;
}
