#include "atlas/charts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <utility>

#include "atlas/base/used_vertices.h"
#include "atlas/bound/cut_invalid_charts.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/measure/least_gutter.h"
#include "atlas/measure/valid_as_stored.h"
#include "atlas/prepare/prepare_input.h"
#include "atlas/search/make_atlas.h"

namespace lowstretch {

Error check_chart_options(const ChartOptions& o) {
  if (!(o.max_stretch >= 1 && o.max_stretch < 1e6))
    return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + number_text(o.max_stretch), "max_stretch"};
  if (o.most_cuts_ahead < 0 || o.most_cuts_ahead > 16)
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 16, got " + std::to_string(o.most_cuts_ahead), "most_cuts_ahead"};
  if (!(o.min_efficiency >= 0 && o.min_efficiency <= 1))
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 1, got " + number_text(o.min_efficiency), "min_efficiency"};
  if (o.max_charts < 1) return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + std::to_string(o.max_charts), "max_charts"};
  if (o.texture_size < 8 || o.texture_size > 65536)
    return {ErrorCode::InvalidOption, 0, "must be from 8 to 65536, got " + std::to_string(o.texture_size), "texture_size"};
  if (!(o.gutter >= 0.5 && o.gutter <= o.texture_size / 8.0))
    return {ErrorCode::InvalidOption, 0, "must be from 0.5 to an eighth of the texture size (" +
                                             number_text(o.texture_size / 8.0) + "), got " + number_text(o.gutter),
            "gutter"};
  return {};
}

namespace {

// A disk as one chart: parameterize's map and pass history; measured later, like a layout.
ChartsResult from_disk(const Eigen::MatrixXi& F, Result disk) {
  ChartsResult result;
  result.input_is_disk = true;
  result.corner_uv.resize(F.rows(), 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) result.corner_uv.block(f, 2 * k, 1, 2) = disk.uv.row(F(f, k));
  result.face_chart.assign(size_t(F.rows()), 0);
  for (const PassMetrics& p : disk.passes) result.passes.push_back({p.pass, p.l2_stretch, p.flipped, p.degenerate});
  Chart chart;
  chart.faces = int(F.rows());
  chart.chosen_pass = disk.chosen_pass;
  chart.passes = int(disk.passes.size());
  result.charts.push_back(chart);
  result.seconds_total = disk.seconds_total;
  result.notes = std::move(disk.notes);
  result.disk_passes = std::move(disk.passes);
  result.chosen_pass = disk.chosen_pass;
  result.stop_reason = disk.stop_reason;
  return result;
}

// parameterize's map of a disk as one chart, stored and measured as MeshLab holds it.
ChartsResult disk_result(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, Result whole,
                         const Eigen::MatrixXd& unit_V, Clock::time_point start) {
  ChartsResult result = from_disk(F, std::move(whole));
  std::vector<int> all(static_cast<size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) all[size_t(f)] = int(f);
  store(unit_V, F, int(V.rows()), {all}, options, result);
  // The layout is the kept pass, as stored: its number, timings and solver stay.
  const PassMetrics measured = result.layout;
  result.layout = result.disk_passes.at(size_t(result.chosen_pass));
  copy_measures(measured, result.layout);
  result.seconds_total = seconds_since(start);
  return result;
}

// A disk keeps the paper's single chart, unless it has flipped or zero-area triangles as stored
// (or, for Atlas, stretches more than the bound) and an atlas uses the texture better; a valid
// map wins over an invalid one, whatever their efficiency. Any other mesh gets the atlas.
ChartsResult disk_or_atlas_of_whole(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                                    Result whole, Clock::time_point start) {
  const bool is_disk = !whole.error;
  if (!is_disk && (options.non_disk == NonDisk::Reject || !cutting_into_disks_fixes(whole.error.code)))
    return failed_result(whole.error);
  ChartsResult disk;
  double unit = 1;
  const Eigen::MatrixXd unit_V = is_disk ? unit_box_of_used(V, F, unit) : Eigen::MatrixXd();
  // Specks are left to the last step, valid_as_stored.
  const auto valid = [&](const ChartsResult& r) {
    return !r.error && without_specks(unit_V, F, r.corner_uv, invalid_faces(unit_V, F, r.corner_uv)).empty();
  };
  bool disk_valid = false;
  if (is_disk) {
    disk = disk_result(V, F, options, std::move(whole), unit_V, start);
    disk_valid = valid(disk);
    const bool try_atlas = options.non_disk == NonDisk::Atlas
                               ? !disk_valid || needs_split(as_chart_pass(disk.disk_passes.at(size_t(disk.chosen_pass))), options.max_stretch)
                               : options.non_disk == NonDisk::Charts && !disk_valid;
    if (!try_atlas) return disk;
  }
  ChartsResult atlas = make_atlas(V, F, options);
  const bool atlas_valid = is_disk && valid(atlas);
  if (is_disk && (atlas.error || (disk_valid != atlas_valid ? disk_valid : !more_efficient(atlas, disk)))) {
    if (!atlas.error)
      disk.notes.push_back("the disk stays one chart: cut into " + std::to_string(atlas.charts.size()) +
                           " charts it had efficiency " + number_text(texture_efficiency(atlas)) + " (coverage / L2^2) against " +
                           number_text(texture_efficiency(disk)));
    return disk;
  }
  atlas.seconds_total = seconds_since(start);
  atlas.layout.seconds = atlas.seconds_total;
  return atlas;
}

// The input prepared (prepare_input.h), charted, and the charts given back for the input. Where the
// welded copy's charts fail, the input is charted without welding.
ChartsResult disk_or_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options) {
  const Clock::time_point start = Clock::now();
  ChartsResult result;
  for (const bool may_weld : {true, false}) {
    PreparedInput prepared = prepare_input(V, F, options, may_weld);
    result = prepared.error ? failed_result(prepared.error)
                            : disk_or_atlas_of_whole(prepared.V, prepared.F, options, std::move(prepared.whole), start);
    result = give_back(prepared, std::move(result), options);
    if (!result.error && !prepared.steps.empty()) result.seconds_total = seconds_since(start);
    const bool welded = std::any_of(prepared.steps.begin(), prepared.steps.end(),
                                    [](const PrepareStep& step) { return step.kind == PrepareStep::Kind::Weld; });
    if (!result.error || !welded) break;
  }
  return result;
}

}  // namespace

void measure_gutter(const ChartOptions& options, ChartsResult& result) {
  if (result.error) return;
  const double texel = 1.0 / options.texture_size;
  result.least_gutter = least_gutter(result.corner_uv, result.face_chart, 2 * options.gutter * texel) / texel;
}

ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options) {
  if (Error e = check_chart_options(options)) return failed_result(e);
  ChartsResult result = disk_or_atlas(V, F, options);
  if (result.error) return result;
  double unit = 1;
  const Eigen::MatrixXd unit_V = unit_box_of_used(V, F, unit);
  double in_stages = 0;
  for (const StageSeconds& stage : result.stage_seconds) in_stages += stage.seconds;
  result.stage_seconds.insert(result.stage_seconds.begin(), {"input and whole map", std::max(0.0, result.seconds_total - in_stages)});
  const Clock::time_point start = Clock::now();
  result = valid_as_stored(unit_V, F, unit, int(V.rows()), options, std::move(result));
  measure_gutter(options, result);
  result.stage_seconds.push_back({"valid as stored", seconds_since(start)});
  result.seconds_total += result.stage_seconds.back().seconds;
  return result;
}

}  // namespace lowstretch
