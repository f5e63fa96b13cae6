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
#include "core/errors.h"
#include "core/parameterize.h"
#include "plugin_common/result_lines.h"
#include "vcg_arrays/mesh_arrays.h"

namespace lowstretch {
namespace plugin {

extern const char* const kFilterName;  // the display name, also the name .mlx scripts use
extern const char* const kPythonName;  // the pymeshlab name (FilterPlugin::pythonFilterName)
extern const char* const kPluginName;
extern const char* const kFilterInfo;  // HTML shown in MeshLab's filter dialog

// A parameter as MeshLab shows it. `name` is what scripts spell (.mlx; pymeshlab lowercases it).
struct EnumParameter {
  const char* name;
  int default_index;
  std::vector<const char*> entries;  // in the order of the core's enum
  const char* label;
  const char* tooltip;
};
struct FloatParameter {
  const char* name;
  double default_value;
  const char* label;
  const char* tooltip;
};
struct IntParameter {
  const char* name;
  int default_value;
  const char* label;
  const char* tooltip;
};
struct BoolParameter {
  const char* name;
  bool default_value;
  const char* label;
  const char* tooltip;
};
// The filter's parameters, in the order the dialog lists them.
struct Parameters {
  EnumParameter boundary;
  FloatParameter exponent;
  IntParameter max_passes;
  EnumParameter weights;
  EnumParameter non_disk;
  FloatParameter max_stretch;
  IntParameter texture_size;
  FloatParameter gutter;
  BoolParameter refine;
};
const Parameters& parameters();
// An enum parameter's entries as MeshLab's RichEnum takes them.
QStringList entries(const EnumParameter& p);

// The core's options from the parameter values as MeshLab hands them over. On an invalid value
// returns an InvalidOption error whose detail names the parameter by its label; options is then
// left as it was.
struct ParameterValues {
  int boundary, weights;
  double exponent;
  int max_passes, non_disk;
  double max_stretch;
  int texture_size;
  double gutter;
  bool refine;
};
Error make_options(const ParameterValues& values, ChartOptions& options);
// The dialog's label of an option the core names in an InvalidOption error ("exponent").
std::string label_of(const std::string& option);

// The filter's parameters into a MeshLab RichParameterList, in the dialog's order. Both plugin
// APIs name their parameter classes alike; Scalar is the float type of the MeshLab build.
template <class Scalar, class List, class Enum, class Float, class Int, class Bool>
void add_parameters(List& list) {
  const Parameters& p = parameters();
  list.addParam(Enum(p.boundary.name, p.boundary.default_index, entries(p.boundary), p.boundary.label, p.boundary.tooltip));
  list.addParam(Float(p.exponent.name, Scalar(p.exponent.default_value), p.exponent.label, p.exponent.tooltip));
  list.addParam(Int(p.max_passes.name, p.max_passes.default_value, p.max_passes.label, p.max_passes.tooltip));
  list.addParam(Enum(p.weights.name, p.weights.default_index, entries(p.weights), p.weights.label, p.weights.tooltip));
  list.addParam(Enum(p.non_disk.name, p.non_disk.default_index, entries(p.non_disk), p.non_disk.label, p.non_disk.tooltip));
  list.addParam(Float(p.max_stretch.name, Scalar(p.max_stretch.default_value), p.max_stretch.label, p.max_stretch.tooltip));
  list.addParam(Int(p.texture_size.name, p.texture_size.default_value, p.texture_size.label, p.texture_size.tooltip));
  list.addParam(Float(p.gutter.name, Scalar(p.gutter.default_value), p.gutter.label, p.gutter.tooltip));
  list.addParam(Bool(p.refine.name, p.refine.default_value, p.refine.label, p.refine.tooltip));
}

// make_options from the values a MeshLab RichParameterList holds (getEnum, getFloat, getInt,
// getBool in both APIs).
template <class List>
Error options_from(const List& values, ChartOptions& options) {
  const Parameters& p = parameters();
  return make_options({values.getEnum(p.boundary.name), values.getEnum(p.weights.name), values.getFloat(p.exponent.name),
                       values.getInt(p.max_passes.name), values.getEnum(p.non_disk.name), values.getFloat(p.max_stretch.name),
                       values.getInt(p.texture_size.name), values.getFloat(p.gutter.name), values.getBool(p.refine.name)},
                      options);
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

// The filter's output values (pymeshlab returns them as a dict): metrics of the kept pass (of the
// whole layout for charts; kept_pass is then -1 and passes counts those of every chart), charts,
// seam length and coverage.
struct OutputValue {
  std::string name;
  bool is_int;
  int int_value;
  double real_value;
};
std::vector<OutputValue> output_values(const ChartsResult& result);

// One run on a vcglib mesh: logs the header, converts the live elements, runs the core, logs the
// result. `error` is empty on success, else the message for the user; the mesh is not touched
// either way (the adapter writes the result with write_result after enabling the components).
struct Run {
  std::string error;
  ArrayRows rows;
  ChartsResult result;
};
template <class MeshType>
Run run(const MeshType& m, const ChartOptions& options, const std::function<void(const std::string&)>& log) {
  log(header_line(m.vn, m.fn, options));
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  Run run;
  run.rows = mesh_to_arrays(m, V, F);
  try {
    run.result = parameterize_charts(V, F, options);
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

// Writes a successful run into the mesh.
template <class MeshType>
void write_result(MeshType& m, const Run& run) {
  write_parameterization(m, run.rows, run.result);
}


// The checkerboard texture: "filter_lowstretch/checkerboard.png" next to the plugin file (it is
// installed there, and copied there in the build tree). The plugin may be loaded through a
// symlink, so both the path it was loaded from and its real path are tried. Empty if not found.
QString checkerboard_path();

// The MeshModel data the filter writes (wedge and vertex texcoords, vertex and face quality); the
// MM_* names are the same in both MeshLab APIs.
template <class MeshModelType>
int written_data_mask() {
  return MeshModelType::MM_WEDGTEXCOORD | MeshModelType::MM_VERTTEXCOORD | MeshModelType::MM_VERTQUALITY |
         MeshModelType::MM_FACEQUALITY;
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
  write_result(m.cm, result);
  return result;
}

}  // namespace plugin
}  // namespace lowstretch
