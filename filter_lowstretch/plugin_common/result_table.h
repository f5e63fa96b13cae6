// Every summary value of a run, described once: its name in pymeshlab's output dict (and the
// filter's output values), its key in the tool's JSON and what it means. The filters' output
// values, the tool's JSON summary and the README's list of outputs are made from this table.
#pragma once
#include <string>
#include <vector>

#include "atlas/charts.h"

namespace lowstretch {

struct ResultRow {
  const char* name;      // pymeshlab's key
  const char* json_key;  // the tool's JSON key, nullptr where the JSON holds it in its own shape
  bool is_int;
  const char* help;
  double (*get)(const ChartsResult&);
};

const std::vector<ResultRow>& result_table();

struct OutputValue {
  std::string name;
  bool is_int;
  int int_value;
  double real_value;
};
// The values of every row for one successful run.
std::vector<OutputValue> output_values(const ChartsResult& result);
// The list of outputs for filter_lowstretch/README.md, as a Markdown table.
std::string results_markdown();

}  // namespace lowstretch
