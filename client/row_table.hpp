#pragma once
// Printing query rows (JSON objects) as an aligned table, CSV or JSON. Walker solutions print as
// one line per point with the quantities users look for first (point_table.hpp); other rows, and
// every row with `wide`, as one column per scalar, nested "values" objects spliced in as columns
// of their own (other nested data is left to JSON). Times (columns "at", "..._at") print as ISO
// 8601 UTC in tables and CSV; JSON keeps Unix seconds.

#include <nlohmann/json.hpp>

#include <ostream>

namespace cyclopt::client {

enum class RowFormat { table, wide, csv, json };

void print_rows(std::ostream& out, const nlohmann::json& rows, RowFormat format);

}  // namespace cyclopt::client
