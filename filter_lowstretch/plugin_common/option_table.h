// Every option a user can set, described once: its names in the tool, MeshLab and pymeshlab, its
// type, range, default and help. The tool's parser and usage, both filters' parameters, their log
// header and the option reference in filter_lowstretch/README.md are made from this table.
// Adding an option is one row here plus its use in the core or the atlas.
#pragma once
#include <string>
#include <vector>

#include "atlas/charts.h"

namespace lowstretch {

enum class OptionKind { Choice, Real, Whole, Switch };

// Where an option is offered: the tool only (solver choices for benchmarks) or everywhere.
enum OptionPlaces { kToolOnly = 1, kToolAndFilter = 3 };

struct OptionRow {
  const char* name;         // as the core names it in an InvalidOption error ("max_stretch")
  const char* flag;         // the tool's flag ("--max-stretch")
  const char* script_name;  // the filter parameter in .mlx scripts; pymeshlab spells it in lower case
  const char* label;        // the filter dialog's label
  OptionKind kind;
  std::vector<const char*> words;    // Choice: the tool's values, in the order of the core's enum
  std::vector<const char*> entries;  // Choice: the dialog's entries, in the same order
  const char* range;        // Real, Whole: what the core accepts (it checks and names the option)
  OptionPlaces places;
  const char* help;         // the dialog's tooltip, the tool's help and the README's text
  // The value as a number (a Choice's index, a Switch's 0 or 1) read from and written to options.
  double (*get)(const ChartOptions&);
  void (*set)(ChartOptions&, double);
};

const std::vector<OptionRow>& option_table();
// The row of an option by its core name, or nullptr.
const OptionRow* option_named(const std::string& name);
// A row's value in `options` as the user would type it ("square", "1.2", "off").
std::string value_text(const OptionRow& row, const ChartOptions& options);
// The same in default ChartOptions.
std::string default_text(const OptionRow& row);
// The option reference of filter_lowstretch/README.md, as a Markdown table.
std::string options_markdown();

}  // namespace lowstretch
