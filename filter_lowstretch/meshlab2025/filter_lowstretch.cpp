#include "meshlab2025/filter_lowstretch.h"

#include <QImage>

#include <common/mlexception.h>

#include "plugin_common/lowstretch_filter.h"

namespace plugin = lowstretch::plugin;

FilterLowStretchPlugin::FilterLowStretchPlugin() {
  typeList = {FP_LOW_STRETCH};
  for (ActionIDType type : types()) actionList.push_back(new QAction(filterName(type), this));
}

QString FilterLowStretchPlugin::pluginName() const { return plugin::kPluginName; }

QString FilterLowStretchPlugin::vendor() const { return "filter_lowstretch"; }

QString FilterLowStretchPlugin::filterName(ActionIDType) const { return plugin::kFilterName; }

QString FilterLowStretchPlugin::pythonFilterName(ActionIDType) const { return plugin::kPythonName; }

QString FilterLowStretchPlugin::filterInfo(ActionIDType) const { return plugin::kFilterInfo; }

FilterPlugin::FilterClass FilterLowStretchPlugin::getClass(const QAction*) const { return FilterPlugin::Texture; }

// Nothing is asked of the framework before applyFilter: a failing run must leave the masks as they were.
int FilterLowStretchPlugin::getRequirements(const QAction*) { return MeshModel::MM_NONE; }

int FilterLowStretchPlugin::getPreConditions(const QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterLowStretchPlugin::postCondition(const QAction*) const { return plugin::written_data_mask<MeshModel>(); }

FilterPlugin::FilterArity FilterLowStretchPlugin::filterArity(const QAction*) const { return SINGLE_MESH; }

RichParameterList FilterLowStretchPlugin::initParameterList(const QAction*, const MeshModel&) {
  RichParameterList parameters;
  plugin::add_parameters<Scalarm, RichParameterList, RichEnum, RichFloat, RichInt, RichBool>(parameters);
  return parameters;
}

void FilterLowStretchPlugin::fail(const std::string& message) const {
  log(plugin::failure_line(message));
  throw MLException(QString::fromStdString(message));
}

std::map<std::string, QVariant> FilterLowStretchPlugin::applyFilter(const QAction*, const RichParameterList& parameters,
                                                                    MeshDocument& md, unsigned int& postConditionMask,
                                                                    vcg::CallBackPos* cb) {
  if (md.mm() == nullptr) fail("no mesh is loaded");
  MeshModel& m = *md.mm();

  const plugin::Run run = plugin::apply(m, parameters, cb, [this](const std::string& line) { log(line); });
  if (!run.error.empty()) fail(run.error);
  const int written = plugin::written_data_mask<MeshModel>(run.vertex_texcoords);
  // Every wedge now refers to texture 0. MeshLab 2022+ keeps the image with the mesh and saves it
  // next to the mesh file under the texture's name.
  m.clearTextures();
  const QImage checkerboard(plugin::checkerboard_path());
  if (checkerboard.isNull())
    log("note: checkerboard.png was not found next to the plugin; no texture attached");
  else
    m.addTexture("checkerboard.png", checkerboard);
  postConditionMask = unsigned(written);

  std::map<std::string, QVariant> values;
  for (const lowstretch::OutputValue& v : lowstretch::output_values(run.result))
    values[v.name] = v.is_int ? QVariant(v.int_value) : QVariant(v.real_value);
  return values;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterLowStretchPlugin)
