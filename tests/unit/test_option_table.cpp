// The option and result tables (plugin_common/option_table.h, result_table.h): names unique, every
// value round-trips through the options, the core names its errors by the table's names, and the
// README's reference is the table's.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "generated_meshes.h"
#include "plugin_common/option_table.h"
#include "plugin_common/result_table.h"

using namespace lowstretch;
using testmesh::Mesh;
using testmesh::grid;
using testmesh::two_grids;

namespace {

// The text between "<!-- NAME: begin -->\n" and "<!-- NAME: end -->" in filter_lowstretch/README.md.
std::string readme_section(const std::string& name) {
  std::ifstream in(LOWSTRETCH_SOURCE_DIR "/filter_lowstretch/README.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str(), begin = "<!-- " + name + ": begin -->\n", end = "<!-- " + name + ": end -->";
  const size_t from = all.find(begin), to = all.find(end);
  if (from == std::string::npos || to == std::string::npos) return "no section " + name;
  return all.substr(from + begin.size(), to - from - begin.size());
}

ChartsResult run_with(const std::function<void(ChartOptions&)>& change) {
  const Mesh disk = grid(6, [](double x, double y) { return 0.3 * x * y; });
  ChartOptions options;
  change(options);
  return parameterize_charts(disk.V, disk.F, options);
}

}  // namespace

TEST(OptionTable, NamesAreUnique) {
  std::set<std::string> names, flags, scripts, labels;
  for (const OptionRow& row : option_table()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    EXPECT_TRUE(flags.insert(row.flag).second) << row.flag;
    if (row.places != kToolAndFilter) continue;
    std::string lower = row.script_name;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_TRUE(scripts.insert(lower).second) << row.script_name;  // pymeshlab lowercases them
    EXPECT_TRUE(labels.insert(row.label).second) << row.label;
  }
}

TEST(OptionTable, EveryValueRoundTrips) {
  for (const OptionRow& row : option_table()) {
    std::vector<double> values;
    if (row.kind == OptionKind::Choice) {
      if (row.places == kToolAndFilter) EXPECT_EQ(row.words.size(), row.entries.size()) << row.name;
      for (size_t i = 0; i < row.words.size(); ++i) values.push_back(double(i));
    } else if (row.kind == OptionKind::Switch) {
      values = {0, 1};
    } else {
      values = {row.get(ChartOptions()), 3};
    }
    for (double value : values) {
      ChartOptions options;
      row.set(options, value);
      EXPECT_EQ(row.get(options), value) << row.name;
      for (const OptionRow& other : option_table())  // and no other option moved
        if (&other != &row) EXPECT_EQ(other.get(options), other.get(ChartOptions())) << row.name << " moved " << other.name;
    }
  }
}

TEST(OptionTable, DefaultsAreAccepted) {
  const ChartsResult result = run_with([](ChartOptions&) {});
  EXPECT_FALSE(result.error) << message(result.error);
  EXPECT_EQ(default_text(*option_named("boundary")), "square");
  EXPECT_EQ(default_text(*option_named("max_stretch")), "1.2");
  EXPECT_EQ(default_text(*option_named("refine")), "off");
}

// The core and the atlas check the values; the tool and the filters name the option from the
// table, so every name the core gives must be a row's.
TEST(OptionTable, TheCoreNamesRejectedValuesByTheTable) {
  const std::vector<std::pair<std::string, double>> bad = {
      {"exponent", 0}, {"exponent", 1.5}, {"max_passes", -1}, {"max_passes", 1001}, {"max_stretch", 0.99},
      {"texture_size", 7}, {"texture_size", 65537}, {"gutter", 0.4}, {"gutter", 129}, {"max_charts", 0},
      {"refine_iterations", 0}, {"refine_iterations", 10001}};
  for (const auto& b : bad) {
    const OptionRow* row = option_named(b.first);
    ASSERT_NE(row, nullptr) << b.first;
    const ChartsResult result = run_with([&](ChartOptions& o) { row->set(o, b.second); });
    EXPECT_EQ(result.error.code, ErrorCode::InvalidOption) << b.first << " " << b.second;
    EXPECT_EQ(result.error.option, b.first);
  }
  const std::vector<std::pair<std::string, double>> edges = {
      {"exponent", 1}, {"max_passes", 0}, {"max_stretch", 1}, {"texture_size", 16}, {"gutter", 0.5},
      {"refine_iterations", 1}};  // 16: the default gutter is an eighth
  for (const auto& e : edges) {
    const ChartsResult result = run_with([&](ChartOptions& o) { option_named(e.first)->set(o, e.second); });
    EXPECT_FALSE(result.error) << e.first << " " << e.second << ": " << message(result.error);
  }
}

TEST(OptionTable, ReadmeIsTheTable) {
  EXPECT_EQ(readme_section("options"), options_markdown())
      << "paste this between the options markers of filter_lowstretch/README.md:\n" << options_markdown();
  EXPECT_EQ(readme_section("results"), results_markdown())
      << "paste this between the results markers of filter_lowstretch/README.md:\n" << results_markdown();
}

TEST(ResultTable, ValuesMatchTheResult) {
  const ChartsResult disk = run_with([](ChartOptions&) {});
  ASSERT_FALSE(disk.error);
  std::set<std::string> names, keys;
  for (const ResultRow& row : result_table()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    if (row.json_key) EXPECT_TRUE(keys.insert(row.json_key).second) << row.json_key;
  }
  std::map<std::string, double> value;
  for (const OutputValue& v : output_values(disk)) value[v.name] = v.is_int ? v.int_value : v.real_value;
  EXPECT_EQ(value["charts"], 1);
  EXPECT_EQ(value["kept_pass"], disk.chosen_pass);
  EXPECT_EQ(value["passes"], double(disk.disk_passes.size()));
  EXPECT_EQ(value["l2_stretch"], disk.layout.l2_stretch);
  // Efficiency is coverage / L2^2, computed from the table's own values.
  EXPECT_NEAR(value["efficiency"], value["coverage"] / (value["l2_stretch"] * value["l2_stretch"]), 1e-12);

  const Mesh two = two_grids(4);
  const ChartsResult charts = parameterize_charts(two.V, two.F, ChartOptions());
  ASSERT_FALSE(charts.error);
  value.clear();
  for (const OutputValue& v : output_values(charts)) value[v.name] = v.is_int ? v.int_value : v.real_value;
  EXPECT_EQ(value["charts"], double(charts.charts.size()));
  EXPECT_GE(value["charts"], 2);
  EXPECT_EQ(value["kept_pass"], -1);
  EXPECT_TRUE(std::isnan(value["initial_l2_stretch"]));
}
