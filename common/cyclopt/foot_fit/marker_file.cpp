#include "cyclopt/foot_fit/marker_file.hpp"

#include "cyclopt/foot_fit/marker_csv_file.hpp"
#include "cyclopt/foot_fit/trc_file.hpp"

#include <filesystem>
#include <stdexcept>

namespace cyclopt::foot_fit {

MarkerTrial read_marker_file(const std::string& path, const std::optional<std::string>& units) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".trc") return read_trc(path);
  if (ext == ".csv") return read_marker_csv(path, units);
  throw std::invalid_argument(path + ": unknown file type '" + ext + "' (.trc or .csv)");
}

}  // namespace cyclopt::foot_fit
