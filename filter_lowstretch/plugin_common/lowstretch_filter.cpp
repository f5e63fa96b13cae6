#include "plugin_common/lowstretch_filter.h"

#include <dlfcn.h>

#include <QFileInfo>
#include <cmath>
#include <cstdio>

namespace lowstretch {
namespace plugin {

const char* const kFilterName = "Low-stretch parameterization";
const char* const kPythonName = "compute_texcoord_parametrization_low_stretch";
const char* const kPluginName = "FilterLowStretch";
const char* const kFilterInfo =
    "Low-stretch texture coordinates: a disk as one chart, any other mesh as an atlas of charts.<br>"
    "Writes wedge and vertex texture coordinates and stretch as vertex and face quality; the log gives the metrics.<br>"
    "Yoshizawa, Belyaev, Seidel, <i>A fast and simple stretch-minimizing mesh parameterization</i>, SMI 2004.";

QStringList entries(const OptionRow& row) {
  QStringList list;
  for (const char* entry : row.entries) list << entry;
  return list;
}

std::string label_of(const std::string& option) {
  const OptionRow* row = option_named(option);
  return row != nullptr && row->places == kToolAndFilter ? row->label : option;
}

// "Boundary shape must be 0 (Square), 1 (Circle) or 2 (Natural), got 3"
Error invalid_choice(const OptionRow& row, int value) {
  std::string choices;
  for (size_t i = 0; i < row.entries.size(); ++i) {
    if (i > 0) choices += i + 1 == row.entries.size() ? " or " : ", ";
    choices += std::to_string(i) + " (" + row.entries[i] + ")";
  }
  return {ErrorCode::InvalidOption, 0, std::string(row.label) + " must be " + choices + ", got " + std::to_string(value)};
}

// "Low-stretch parameterization: 100 vertices, 180 faces; boundary square, exponent 1, ..." (the
// options by the names scripts and the tool's JSON use)
std::string header_line(int vertices, int faces, const ChartOptions& options) {
  std::string line = format("%s: %d vertices, %d faces", kFilterName, vertices, faces);
  const char* separator = "; ";
  for (const OptionRow& row : option_table()) {
    if (row.places != kToolAndFilter) continue;
    line += separator + std::string(row.name) + " " + value_text(row, options);
    separator = ", ";
  }
  return line;
}

std::string failure_line(const std::string& message) { return std::string(kFilterName) + " failed: " + message; }

QString checkerboard_path() {
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&checkerboard_path), &info) == 0 || info.dli_fname == nullptr) return {};
  const QFileInfo plugin(QString::fromLocal8Bit(info.dli_fname));
  for (const QString& dir : {plugin.absolutePath(), QFileInfo(plugin.canonicalFilePath()).absolutePath()}) {
    const QFileInfo texture(dir + "/filter_lowstretch/checkerboard.png");
    if (texture.isFile()) return texture.absoluteFilePath();
  }
  return {};
}

}  // namespace plugin
}  // namespace lowstretch
