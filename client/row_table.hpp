#pragma once
// Printing query rows (JSON objects) as an aligned table, CSV or JSON. Nested "values" objects
// (a solution's per-kind results) become columns of their own; other nested data is dropped
// from tables and CSV.

#include <nlohmann/json.hpp>

#include <ostream>

namespace cyclopt::client {

enum class RowFormat { table, csv, json };

void print_rows(std::ostream& out, const nlohmann::json& rows, RowFormat format);

}  // namespace cyclopt::client
