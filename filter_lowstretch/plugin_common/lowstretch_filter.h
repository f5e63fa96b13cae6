// What every MeshLab adapter of the "Low-stretch parameterization" filter shares, whatever the
// plugin API (MeshLab 2020.09's MeshFilterInterface, MeshLab 2022+'s FilterPlugin): the names and
// texts, the parameters (name, default, label, tooltip, enum entries), the check of the parameter
// values, the log lines, the run itself (vcglib mesh -> core -> log) and the output values.
// An adapter only translates these into its API's types and writes the result into the mesh.
// Nothing here knows MeshModel or RichParameter; the mesh side is vcglib (mesh_arrays.h).
#pragma once
#include <QString>
#include <QStringList>
#include <algorithm>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "atlas/charts.h"
#include "atlas/repack.h"
#include "core/errors.h"
#include "core/parameterize.h"
#include "plugin_common/one_blas_thread.h"
#include "plugin_common/option_table.h"
#include "plugin_common/result_lines.h"
#include "plugin_common/result_table.h"
#include "vcg_arrays/mesh_arrays.h"

namespace lowstretch {
namespace plugin {

extern const char* const kFilterName;  // the display name, also the name .mlx scripts use
extern const char* const kPythonName;  // the pymeshlab name (FilterPlugin::pythonFilterName)
extern const char* const kPluginName;
extern const char* const kFilterInfo;  // HTML shown in MeshLab's filter dialog

// An option's dialog entries as MeshLab's RichEnum takes them.
QStringList entries(const OptionRow& row);
// The option the core names in an InvalidOption error ("exponent"), by its dialog label.
std::string label_of(const std::string& option);
// A dialog value that is no entry of its option's list.
Error invalid_choice(const OptionRow& row, int value);

// The filter's parameters (the option table's rows for the filter, in its order) into a MeshLab
// RichParameterList. Both plugin APIs name their parameter classes alike; Scalar is the float type
// of the MeshLab build.
template <class Scalar, class List, class Enum, class Float, class Int, class Bool>
void add_parameters(List& list) {
  const ChartOptions defaults;
  for (const OptionRow& row : option_table()) {
    if (row.places != kToolAndFilter) continue;
    const double value = row.get(defaults);
    switch (row.kind) {
      case OptionKind::Choice: list.addParam(Enum(row.script_name, int(value), entries(row), row.label, row.help)); break;
      case OptionKind::Real: list.addParam(Float(row.script_name, Scalar(value), row.label, row.help)); break;
      case OptionKind::Whole: list.addParam(Int(row.script_name, int(value), row.label, row.help)); break;
      case OptionKind::Switch: list.addParam(Bool(row.script_name, value != 0, row.label, row.help)); break;
    }
  }
}

// The options from the values a MeshLab RichParameterList holds (getEnum, getFloat, getInt, getBool
// in both APIs). An enum value outside its list is an InvalidOption error naming the parameter by
// its label, and options is then left as it was; the core checks the other values.
template <class List>
Error options_from(const List& values, ChartOptions& options) {
  ChartOptions made = options;
  for (const OptionRow& row : option_table()) {
    if (row.places != kToolAndFilter) continue;
    double value = 0;
    switch (row.kind) {
      case OptionKind::Choice: {
        const int index = values.getEnum(row.script_name);
        if (index < 0 || index >= int(row.entries.size())) return invalid_choice(row, index);
        value = index;
        break;
      }
      case OptionKind::Real: value = values.getFloat(row.script_name); break;
      case OptionKind::Whole: value = values.getInt(row.script_name); break;
      case OptionKind::Switch: value = values.getBool(row.script_name) ? 1 : 0; break;
    }
    row.set(made, value);
  }
  options = made;
  return {};
}

// Maps MeshLab's progress callback (percent, stage; false cancels) to the core's.
template <class CallBack>
std::function<bool(double, const char*)> progress(CallBack* cb) {
  return [cb](double fraction, const char* stage) {
    return cb == nullptr || cb(int(100 * std::min(1.0, std::max(0.0, fraction))), stage);
  };
}

// Log lines, exactly as both adapters write them (and result_lines.h for the run itself).
std::string header_line(int vertices, int faces, const ChartOptions& options);
std::string failure_line(const std::string& message);           // "<filter name> failed: <message>"

// One run on a vcglib mesh: logs the header, converts the live elements, runs the core, logs the
// result. `error` is empty on success, else the message for the user; the mesh is not touched
// either way (the adapter writes the result with write_result after enabling the components).
// OpenBLAS is held at one thread for the call, as the tool holds it (one_blas_thread.h), and its
// count is restored after.
struct Run {
  std::string error;
  ArrayRows rows;
  ChartsResult result;
  bool vertex_texcoords = true;  // false: an atlas with seams, written without per-vertex texcoords
};
template <class MeshType>
Run run(const MeshType& m, const ChartOptions& options, const std::function<void(const std::string&)>& log) {
  log(header_line(m.vn, m.fn, options));
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  Run run;
  run.rows = mesh_to_arrays(m, V, F);
  const OneBlasThread one_blas_thread;
  try {
    run.result = options.repack ? repack_atlas(V, F, wedge_texcoords(m, run.rows), options) : parameterize_charts(V, F, options);
  } catch (const std::exception& e) {  // e.g. std::bad_alloc: never let it reach MeshLab's event loop
    run.error = std::string("internal error: ") + e.what();
    return run;
  }
  if (run.result.error) {
    run.error = message(run.result.error, label_of);
    if (charts_would_help(run.result.error.code)) run.error += " (set \"Non-disk input\" to Make charts or Atlas for any mesh)";
    return run;
  }
  for (const std::string& line : result_lines(run.result)) log(line);
  return run;
}

// Writes a successful run into the mesh; returns whether every vertex has one texcoord (no seam).
template <class MeshType>
bool write_result(MeshType& m, const Run& run) {
  return write_parameterization(m, run.rows, run.result);
}


// The checkerboard texture: "filter_lowstretch/checkerboard.png" next to the plugin file (it is
// installed there, and copied there in the build tree). The plugin may be loaded through a
// symlink, so both the path it was loaded from and its real path are tried. Empty if not found.
QString checkerboard_path();

// The MeshModel data the filter writes (wedge and vertex texcoords, vertex and face quality); the
// MM_* names are the same in both MeshLab APIs. An atlas with seams has no per-vertex texcoords.
template <class MeshModelType>
int written_data_mask(bool vertex_texcoords = true) {
  return MeshModelType::MM_WEDGTEXCOORD | (vertex_texcoords ? int(MeshModelType::MM_VERTTEXCOORD) : 0) |
         MeshModelType::MM_VERTQUALITY | MeshModelType::MM_FACEQUALITY;
}

// The filter as both adapters apply it to a MeshModel: options from the dialog's values, the
// run with progress and log, and on success the texcoords and quality enabled and written.
// On failure `error` holds the message and the mesh is untouched.
template <class MeshModelType, class List, class CallBack>
Run apply(MeshModelType& m, const List& values, CallBack* cb, const std::function<void(const std::string&)>& log) {
  ChartOptions options;
  if (const Error invalid = options_from(values, options)) {
    Run failed;
    failed.error = message(invalid, label_of);
    return failed;
  }
  options.disk.progress = progress(cb);
  Run result = run(m.cm, options, log);
  if (!result.error.empty()) return result;
  m.updateDataMask(written_data_mask<MeshModelType>());
  // Where a vertex has a texcoord per chart, a per-vertex texcoord would hold one of them: MeshLab's
  // ASCII PLY writer takes it for every wedge of the vertex, moving seam corners into other charts.
  result.vertex_texcoords = write_result(m.cm, result);
  if (!result.vertex_texcoords) m.clearDataMask(MeshModelType::MM_VERTTEXCOORD);
  return result;
}

}  // namespace plugin
}  // namespace lowstretch
