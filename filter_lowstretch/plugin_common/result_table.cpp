#include "plugin_common/result_table.h"

#include <cmath>
#include <sstream>

namespace lowstretch {

namespace {

// Passes computed: a disk's (including a rejected last one), or every chart's summed.
double passes_computed(const ChartsResult& r) {
  if (r.input_is_disk) return double(r.disk_passes.size());
  double passes = 0;
  for (const Chart& c : r.charts) passes += c.passes;
  return passes;
}

std::vector<ResultRow> make_table() {
  // A disk reports its kept pass; charts report the whole layout (no kept pass, no initial map).
  return {
      {"l2_stretch", nullptr, false, "L2 stretch of the map as stored", [](const ChartsResult& r) { return r.layout.l2_stretch; }},
      {"linf_stretch", nullptr, false, "largest triangle stretch", [](const ChartsResult& r) { return r.layout.linf_stretch; }},
      {"edge_distortion", nullptr, false, "edge length distortion", [](const ChartsResult& r) { return r.layout.edge_distortion; }},
      {"angle_distortion", nullptr, false, "angle distortion", [](const ChartsResult& r) { return r.layout.angle_distortion; }},
      {"area_distortion", nullptr, false, "area distortion", [](const ChartsResult& r) { return r.layout.area_distortion; }},
      {"flipped", nullptr, true, "UV triangles with negative area", [](const ChartsResult& r) { return double(r.layout.flipped); }},
      {"degenerate", nullptr, true, "UV triangles with zero area", [](const ChartsResult& r) { return double(r.layout.degenerate); }},
      {"kept_pass", nullptr, true, "the disk's kept pass; -1 for charts",
       [](const ChartsResult& r) { return r.input_is_disk ? double(r.layout.pass) : -1.0; }},
      {"passes", nullptr, true, "passes computed (for charts, summed over the charts)", passes_computed},
      {"initial_l2_stretch", nullptr, false, "L2 stretch of the disk's initial map U0; NaN for charts",
       [](const ChartsResult& r) { return r.input_is_disk ? r.disk_passes.front().l2_stretch : std::nan(""); }},
      {"seconds", "seconds_total", false, "wall time of the run", [](const ChartsResult& r) { return r.seconds_total; }},
      {"charts", "chart_count", true, "number of charts (1 for a disk)", [](const ChartsResult& r) { return double(r.charts.size()); }},
      {"seam_length", "seam_length", false, "3D length of the seams cut, in the mesh's units",
       [](const ChartsResult& r) { return r.seam_length; }},
      {"coverage", "coverage", false, "share of the texture covered by UV triangles", [](const ChartsResult& r) { return r.coverage; }},
      {"efficiency", "efficiency", false, "coverage / L2^2 (Sander et al. 2001)",
       [](const ChartsResult& r) { return texture_efficiency(r); }},
      {"max_chart_stretch", "max_chart_stretch", false, "highest L2 stretch of one chart",
       [](const ChartsResult& r) { return largest_chart_stretch(r); }},
      {"least_gutter", "least_gutter", false,
       "texels from a chart to another chart or to the border, as stored (looked for up to twice the gutter)",
       [](const ChartsResult& r) { return r.least_gutter; }},
      {"subtexel_triangles", "subtexel_triangles", true, "UV triangles smaller than a texel of a 4096^2 texture",
       [](const ChartsResult& r) { return double(r.subtexel_triangles); }},
      {"float_collapsed", "float_collapsed", true, "of them, flipped or zero in float though positive in double",
       [](const ChartsResult& r) { return double(r.float_collapsed); }},
  };
}

}  // namespace

const std::vector<ResultRow>& result_table() {
  static const std::vector<ResultRow> table = make_table();
  return table;
}

std::vector<OutputValue> output_values(const ChartsResult& result) {
  std::vector<OutputValue> values;
  for (const ResultRow& row : result_table()) {
    const double value = row.get(result);
    values.push_back({row.name, row.is_int, row.is_int ? int(value) : 0, value});
  }
  return values;
}

std::string results_markdown() {
  std::ostringstream md;
  md << "| pymeshlab | tool JSON | meaning |\n|---|---|---|\n";
  for (const ResultRow& row : result_table())
    md << "| `" << row.name << "` | " << (row.json_key ? std::string("`") + row.json_key + "`" : std::string("`layout`, `passes`"))
       << " | " << row.help << " |\n";
  return md.str();
}

}  // namespace lowstretch
