#pragma once
// What the `specula bench` reports' formats share: numbers as text, and rows of named cells written as
// CSV (a header, then a line a row) or JSON (an object a row). A cell left empty was not measured: an
// empty CSV cell, a JSON null and "-" in a table.
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace specula::bench {

// `value` with `decimals` decimals; empty when not finite.
std::string number(double value, int decimals);
// Three significant digits: reflection-point errors span 1e-5 px (exact refinement) to pixels.
std::string significant(double value);
std::string optionalNumber(const std::optional<double>& value, int decimals);
std::string orDash(const std::string& text);

// One named value of a row: a name (`text`) or a number, true or false, as CSV shows it.
struct ReportCell {
  std::string name, value;
  bool text = false;
};
using ReportRow = std::vector<ReportCell>;

// `header` names the columns (its values are ignored); then one line per row.
std::string csvFromRows(const ReportRow& header, std::span<const ReportRow> rows);
// {"<key>": [...]} with one object per row, on a line of its own.
std::string jsonFromRows(const std::string& key, std::span<const ReportRow> rows);

}  // namespace specula::bench
