#include "filter_lowstretch.h"

#include <dlfcn.h>

#include <QFileInfo>
#include <exception>

#include "filter_lowstretch/core/error.h"
#include "filter_lowstretch/core/parameterize.h"
#include "filter_lowstretch/vcg/mesh_arrays.h"

namespace {

// Parameter names as .mlx scripts spell them. Enum entries follow the core's enum order.
const char* const kBoundary = "boundaryShape";
const char* const kExponent = "exponent";
const char* const kMaxPasses = "maxPasses";
const char* const kWeights = "initialWeights";
const QStringList kBoundaryNames{"Square", "Circle", "Natural"};
const QStringList kWeightsNames{"Floater shape-preserving", "Mean value", "Harmonic"};
const lowstretch::BoundaryShape kBoundaryValues[] = {
    lowstretch::BoundaryShape::Square, lowstretch::BoundaryShape::Circle, lowstretch::BoundaryShape::Natural};
const lowstretch::InitialWeights kWeightsValues[] = {
    lowstretch::InitialWeights::Floater, lowstretch::InitialWeights::MeanValue, lowstretch::InitialWeights::Harmonic};

// What the filter writes; postCondition() reports the same set.
const int kWrittenData = MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTTEXCOORD | MeshModel::MM_VERTQUALITY |
                         MeshModel::MM_FACEQUALITY;

lowstretch::Error invalidOption(const std::string& detail) {
  lowstretch::Error error;
  error.code = lowstretch::ErrorCode::InvalidOption;
  error.detail = detail;
  return error;
}

// The checkerboard texture lives in "filter_lowstretch/checkerboard.png" next to the plugin file
// (installed there, and copied there in the build tree). The plugin may be loaded through a
// symlink (test prefixes), so look beside both the path it was loaded from and its real path.
QString checkerboardPath() {
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&checkerboardPath), &info) == 0 || info.dli_fname == nullptr) return {};
  const QFileInfo plugin(QString::fromLocal8Bit(info.dli_fname));
  for (const QString& dir : {plugin.absolutePath(), QFileInfo(plugin.canonicalFilePath()).absolutePath()}) {
    const QFileInfo texture(dir + "/filter_lowstretch/checkerboard.png");
    if (texture.isFile()) return texture.absoluteFilePath();
  }
  return {};
}

}  // namespace

FilterLowStretchPlugin::FilterLowStretchPlugin() {
  typeList << FP_LOW_STRETCH;
  for (FilterIDType type : types()) actionList << new QAction(filterName(type), this);
}

QString FilterLowStretchPlugin::pluginName() const { return "FilterLowStretch"; }

QString FilterLowStretchPlugin::filterName(FilterIDType) const { return "Low-stretch parameterization"; }

QString FilterLowStretchPlugin::filterInfo(FilterIDType) const {
  return "Computes a low-stretch parameterization of a mesh that is a topological disk (connected, "
         "manifold, one boundary loop): the boundary is mapped to a square, a circle or a free "
         "(natural) boundary, the interior starts from Floater's shape-preserving map, and each "
         "pass divides the weights by the vertex stretch and solves again, keeping the pass of "
         "lowest L2 stretch.<br>"
         "Writes per-wedge and per-vertex texture coordinates in [0,1]<sup>2</sup> (texture 0, a "
         "checkerboard), per-vertex quality = vertex stretch and per-face quality = triangle "
         "stretch (use <i>Colorize by vertex/face quality</i> to see where the map stretches). "
         "The log lists the stretch and distortion of every pass. A mesh that is not a disk is "
         "left unchanged and the reason is reported.<br><br>"
         "See: <i>Shin Yoshizawa, Alexander Belyaev, Hans-Peter Seidel</i><br>"
         "<b>\"A fast and simple stretch-minimizing mesh parameterization\"</b><br>"
         "Shape Modeling International 2004, pages 200-208.";
}

MeshFilterInterface::FilterClass FilterLowStretchPlugin::getClass(QAction*) { return MeshFilterInterface::Texture; }

// Nothing is asked of the framework before applyFilter: a failing run must leave the masks as they were.
int FilterLowStretchPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

int FilterLowStretchPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterLowStretchPlugin::postCondition(QAction*) const { return kWrittenData; }

MeshFilterInterface::FILTER_ARITY FilterLowStretchPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

void FilterLowStretchPlugin::initParameterSet(QAction*, MeshModel&, RichParameterList& parameters) {
  const lowstretch::Options defaults;
  parameters.addParam(RichEnum(kBoundary, 0, kBoundaryNames, "Boundary shape",
                               "Where the boundary loop goes: the unit square (the paper's choice), the "
                               "circle (strictly convex: no pass can flip a triangle), or the free boundary "
                               "of a conformal map (least distortion at the boundary; flips are possible "
                               "and are reported)."));
  parameters.addParam(RichFloat(kExponent, float(defaults.exponent), "Exponent",
                                "eta in (0, 1]: each pass divides the weights by the vertex stretch to the "
                                "power eta. 1 is the paper's choice; smaller values redistribute the "
                                "stretch more gently."));
  parameters.addParam(RichInt(kMaxPasses, defaults.max_passes, "Max passes",
                              "At most this many reweighting passes; the run stops earlier when the L2 "
                              "stretch stops falling. 0 gives the initial map only, 1 gives U1."));
  parameters.addParam(RichEnum(kWeights, 0, kWeightsNames, "Initial weights",
                               "Weights of the initial map U0: Floater's shape-preserving weights (the "
                               "paper's choice), mean value weights, or harmonic (cotangent) weights, "
                               "which can be negative and are offered for comparison only."));
}

bool FilterLowStretchPlugin::fail(const std::string& message) {
  errorMessage = QString::fromStdString(message);
  Log("Low-stretch parameterization failed: " + message);
  return false;
}

bool FilterLowStretchPlugin::applyFilter(QAction*, MeshDocument& md, const RichParameterList& parameters,
                                         vcg::CallBackPos* cb) {
  if (md.mm() == nullptr) return fail("no mesh is loaded");
  MeshModel& m = *md.mm();

  const int boundary = parameters.getEnum(kBoundary);
  const int weights = parameters.getEnum(kWeights);
  lowstretch::Options options;
  options.exponent = parameters.getFloat(kExponent);
  options.max_passes = parameters.getInt(kMaxPasses);
  if (boundary < 0 || boundary >= kBoundaryNames.size())
    return fail(lowstretch::message(invalidOption("Boundary shape must be 0 (Square), 1 (Circle) or 2 (Natural), got " +
                                                  std::to_string(boundary))));
  if (weights < 0 || weights >= kWeightsNames.size())
    return fail(lowstretch::message(invalidOption(
        "Initial weights must be 0 (Floater shape-preserving), 1 (Mean value) or 2 (Harmonic), got " +
        std::to_string(weights))));
  if (!(options.exponent > 0 && options.exponent <= 1))
    return fail(lowstretch::message(
        invalidOption("Exponent must be in (0, 1], got " + QString::number(options.exponent).toStdString())));
  if (options.max_passes < 0)
    return fail(lowstretch::message(invalidOption("Max passes must be 0 or more, got " + std::to_string(options.max_passes))));
  options.boundary = kBoundaryValues[boundary];
  options.weights = kWeightsValues[weights];
  options.progress = [cb](double fraction, const char* stage) {
    return cb == nullptr || cb(int(100 * std::min(1.0, std::max(0.0, fraction))), stage);
  };

  Log("Low-stretch parameterization: %d vertices, %d faces; boundary %s, initial weights %s, exponent %g, max passes %d",
      m.cm.vn, m.cm.fn, lowstretch::to_string(options.boundary), lowstretch::to_string(options.weights),
      options.exponent, options.max_passes);

  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const lowstretch::ArrayRows rows = lowstretch::mesh_to_arrays(m.cm, V, F);
  lowstretch::Result result;
  try {
    result = lowstretch::parameterize(V, F, options);
  } catch (const std::exception& e) {  // e.g. std::bad_alloc; meshlabserver would abort otherwise
    return fail(std::string("internal error: ") + e.what());
  }
  if (result.error) return fail(lowstretch::message(result.error));

  for (const lowstretch::PassMetrics& p : result.passes)
    Log("pass %d: L2 stretch %.6g, Linf stretch %.6g, edge distortion %.6g, angle distortion %.6g, "
        "area distortion %.6g, flipped %d, degenerate %d, %.3f s",
        p.pass, p.l2_stretch, p.linf_stretch, p.edge_distortion, p.angle_distortion, p.area_distortion, p.flipped,
        p.degenerate, p.seconds);
  const lowstretch::PassMetrics& kept = result.passes.at(size_t(result.chosen_pass));
  Log("kept pass %d (L2 stretch %.6g); stop reason: %s; total %.3f s", kept.pass, kept.l2_stretch,
      lowstretch::to_string(result.stop_reason), result.seconds_total);
  for (const std::string& note : result.notes) Log("note: " + note);

  m.updateDataMask(kWrittenData);
  lowstretch::write_parameterization(m.cm, rows, result);
  const QString texture = checkerboardPath();
  m.cm.textures.clear();  // every wedge now refers to texture 0
  if (texture.isEmpty())
    Log("note: checkerboard.png was not found next to the plugin; no texture attached");
  else
    m.cm.textures.push_back(texture.toStdString());
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterLowStretchPlugin)
