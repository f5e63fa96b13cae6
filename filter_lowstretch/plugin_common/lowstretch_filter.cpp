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
    "Computes a low-stretch parameterization of a mesh that is a topological disk (connected, "
    "manifold, one boundary loop), or with <i>Non-disk input: Make charts</i> a low-stretch atlas "
    "of any manifold, oriented mesh (<i>Atlas for any mesh</i>: of a disk too): each connected "
    "component becomes a disk chart (holes other than the longest boundary are closed virtually "
    "for the solve and stay holes; closed or higher-genus parts are cut open along short seams), "
    "each chart is mapped onto a rectangle, a chart that stretches more than <i>Max chart "
    "stretch</i> is cut in two and mapped again, and the rectangles tile the texture a gutter "
    "apart at one texel density. For a disk the boundary is mapped to a square, a circle or a free "
    "(natural) boundary, the interior starts from Floater's shape-preserving map, and each "
    "pass divides the weights by the vertex stretch and solves again, keeping the pass of "
    "lowest L2 stretch.<br>"
    "Writes per-wedge and per-vertex texture coordinates inside [0,1]<sup>2</sup>, a gutter of "
    "texels away from its border (texture 0, a checkerboard), per-vertex quality = vertex stretch and per-face quality = triangle "
    "stretch (use <i>Colorize by vertex/face quality</i> to see where the map stretches). "
    "The log lists the stretch and distortion of every pass (for charts, of every chart and of the "
    "whole layout, with the seam length and the fraction of the square covered). A mesh that "
    "cannot be parameterized is left unchanged and the reason is reported.<br><br>"
    "See: <i>Shin Yoshizawa, Alexander Belyaev, Hans-Peter Seidel</i><br>"
    "<b>\"A fast and simple stretch-minimizing mesh parameterization\"</b><br>"
    "Shape Modeling International 2004, pages 200-208.";

namespace {

// The enum entries follow the core's enum order.
const BoundaryShape kBoundaryValues[] = {BoundaryShape::Square, BoundaryShape::Circle, BoundaryShape::Natural};
const InitialWeights kWeightsValues[] = {InitialWeights::Floater, InitialWeights::MeanValue, InitialWeights::Harmonic};
const NonDisk kNonDiskValues[] = {NonDisk::Reject, NonDisk::Charts, NonDisk::Atlas};

Parameters make_parameters() {
  const ChartOptions chart_defaults;
  const Options& defaults = chart_defaults.disk;
  return Parameters{
      EnumParameter{"boundaryShape", 0, {"Square", "Circle", "Natural"}, "Boundary shape",
                    "Where the boundary loop goes: the unit square (the paper's choice), the "
                    "circle (strictly convex: no pass can flip a triangle), or the free boundary "
                    "of a conformal map (least distortion at the boundary; flips are possible "
                    "and are reported)."},
      FloatParameter{"exponent", defaults.exponent, "Exponent",
                     "eta in (0, 1]: each pass divides the weights by the vertex stretch to the "
                     "power eta. 1 is the paper's choice; smaller values redistribute the "
                     "stretch more gently."},
      IntParameter{"maxPasses", defaults.max_passes, "Max passes",
                   "At most this many reweighting passes; the run stops earlier when the L2 "
                   "stretch stops falling. 0 gives the initial map only, 1 gives U1."},
      EnumParameter{"initialWeights", 0, {"Floater shape-preserving", "Mean value", "Harmonic"}, "Initial weights",
                    "Weights of the initial map U0: Floater's shape-preserving weights (the "
                    "paper's choice), mean value weights, or harmonic (cotangent) weights, "
                    "which can be negative and are offered for comparison only."},
      EnumParameter{"nonDisk", int(chart_defaults.non_disk), {"Reject", "Make charts", "Atlas for any mesh"}, "Non-disk input",
                    "What to do with a mesh that is not a disk (holes, closed, handles, several "
                    "parts, non-manifold edges or vertices): reject it with the reason (disk only), "
                    "or make charts (the default): a low-stretch atlas. Every "
                    "part becomes a chart (holes closed virtually, closed parts cut along short "
                    "seams), a chart that stretches more than Max chart stretch is cut in two "
                    "and mapped again, every chart gets a rectangle and the rectangles tile the "
                    "texture a gutter apart. Make charts keeps a disk as one chart (the paper's "
                    "map while it has no flipped or zero-area triangle); Atlas for any mesh cuts a "
                    "disk too when that uses the texture better. Non-manifold edges and vertices "
                    "are cut open for the charts; the mesh itself is not changed."},
      FloatParameter{"maxStretch", chart_defaults.max_stretch, "Max chart stretch",
                     "Charts: a chart whose L2 stretch is above this (at least 1) is cut in two. "
                     "Lower gives less stretch, more charts and longer seams."},
      IntParameter{"textureSize", chart_defaults.texture_size, "Texture size",
                   "Side in texels of the texture the map is made for (the size you give "
                   "Transfer: Vertex Color to Texture): the gutter is measured in its texels."},
      FloatParameter{"gutter", chart_defaults.gutter, "Gutter (texels)",
                     "Every texture coordinate stays this many texels inside the border of the "
                     "texture, so that baking and mipmaps never address a texel outside it "
                     "(at least 0.5)."},
      BoolParameter{"refineStretch", defaults.refine, "Refine stretch",
                    "After the paper's passes, lower the L2 stretch further by minimizing it directly "
                    "(projected Newton, boundary fixed, no triangle flips), for at most 10 times the "
                    "time the passes took. Off: the paper's method alone."},
  };
}

Error invalid(const std::string& detail) {
  Error error;
  error.code = ErrorCode::InvalidOption;
  error.detail = detail;
  return error;
}

// "Boundary shape must be 0 (Square), 1 (Circle) or 2 (Natural), got 3"
Error invalid_enum(const EnumParameter& p, int value) {
  std::string choices;
  for (size_t i = 0; i < p.entries.size(); ++i) {
    if (i > 0) choices += i + 1 == p.entries.size() ? " or " : ", ";
    choices += std::to_string(i) + " (" + p.entries[i] + ")";
  }
  return invalid(std::string(p.label) + " must be " + choices + ", got " + std::to_string(value));
}

}  // namespace

const Parameters& parameters() {
  static const Parameters p = make_parameters();
  return p;
}

QStringList entries(const EnumParameter& p) {
  QStringList list;
  for (const char* entry : p.entries) list << entry;
  return list;
}

Error make_options(const ParameterValues& v, ChartOptions& charts) {
  const Parameters& p = parameters();
  if (v.boundary < 0 || v.boundary >= int(p.boundary.entries.size())) return invalid_enum(p.boundary, v.boundary);
  if (v.weights < 0 || v.weights >= int(p.weights.entries.size())) return invalid_enum(p.weights, v.weights);
  if (v.non_disk < 0 || v.non_disk >= int(p.non_disk.entries.size())) return invalid_enum(p.non_disk, v.non_disk);
  // The values themselves are checked by the core (Options, ChartOptions), which names them;
  // label_of turns its names into the dialog's labels.
  Options& options = charts.disk;
  options.boundary = kBoundaryValues[v.boundary];
  options.weights = kWeightsValues[v.weights];
  options.exponent = v.exponent;
  options.max_passes = v.max_passes;
  charts.non_disk = kNonDiskValues[v.non_disk];
  charts.max_stretch = v.max_stretch;
  charts.texture_size = v.texture_size;
  charts.gutter = v.gutter;
  options.refine = v.refine;
  return {};
}

std::string label_of(const std::string& option) {
  const Parameters& p = parameters();
  if (option == "exponent") return p.exponent.label;
  if (option == "max_passes") return p.max_passes.label;
  if (option == "texture_size") return p.texture_size.label;
  if (option == "gutter") return p.gutter.label;
  if (option == "max_stretch") return p.max_stretch.label;
  return option;
}

std::string header_line(int vertices, int faces, const ChartOptions& charts) {
  const Options& options = charts.disk;
  return format("%s: %d vertices, %d faces; boundary %s, initial weights %s, exponent %g, max passes %d, non-disk input %s, "
                "max chart stretch %g, texture %d, gutter %g texels, refine %s",
                kFilterName, vertices, faces, to_string(options.boundary), to_string(options.weights), options.exponent,
                options.max_passes, to_string(charts.non_disk), charts.max_stretch, charts.texture_size, charts.gutter,
                options.refine ? "on" : "off");
}

std::string failure_line(const std::string& message) { return std::string(kFilterName) + " failed: " + message; }

std::vector<OutputValue> output_values(const ChartsResult& charts) {
  auto real = [](const char* name, double value) { return OutputValue{name, false, 0, value}; };
  auto integer = [](const char* name, int value) { return OutputValue{name, true, value, double(value)}; };
  // A disk reports its kept pass; charts report the whole layout, each chart having kept its own
  // pass (kept_pass -1, passes summed over the charts, no single initial stretch).
  const bool disk = charts.input_is_disk;
  const PassMetrics& p = charts.layout;  // a disk's kept pass
  int passes = int(charts.disk_passes.size());  // computed, including a rejected last one
  if (!disk) {
    passes = 0;
    for (const Chart& c : charts.charts) passes += c.passes;
  }
  return {
      real("l2_stretch", p.l2_stretch),
      real("linf_stretch", p.linf_stretch),
      real("edge_distortion", p.edge_distortion),
      real("angle_distortion", p.angle_distortion),
      real("area_distortion", p.area_distortion),
      integer("flipped", p.flipped),
      integer("degenerate", p.degenerate),
      integer("kept_pass", disk ? p.pass : -1),
      integer("passes", passes),
      real("initial_l2_stretch", disk ? charts.disk_passes.front().l2_stretch : std::nan("")),
      real("seconds", charts.seconds_total),
      integer("charts", int(charts.charts.size())),
      real("seam_length", charts.seam_length),
      real("coverage", charts.coverage),
      real("efficiency", texture_efficiency(charts)),
      real("max_chart_stretch", largest_chart_stretch(charts)),
      integer("subtexel_triangles", charts.subtexel_triangles),
  };
}

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
