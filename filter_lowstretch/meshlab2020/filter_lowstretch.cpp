#include "meshlab2020/filter_lowstretch.h"

#include "plugin_common/lowstretch_filter.h"

namespace plugin = lowstretch::plugin;

FilterLowStretchPlugin::FilterLowStretchPlugin() {
  typeList << FP_LOW_STRETCH;
  for (FilterIDType type : types()) actionList << new QAction(filterName(type), this);
}

QString FilterLowStretchPlugin::pluginName() const { return plugin::kPluginName; }

QString FilterLowStretchPlugin::filterName(FilterIDType) const { return plugin::kFilterName; }

QString FilterLowStretchPlugin::filterInfo(FilterIDType) const { return plugin::kFilterInfo; }

MeshFilterInterface::FilterClass FilterLowStretchPlugin::getClass(QAction*) { return MeshFilterInterface::Texture; }

// Nothing is asked of the framework before applyFilter: a failing run must leave the masks as they were.
int FilterLowStretchPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

int FilterLowStretchPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterLowStretchPlugin::postCondition(QAction*) const { return plugin::written_data_mask<MeshModel>(); }

MeshFilterInterface::FILTER_ARITY FilterLowStretchPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

void FilterLowStretchPlugin::initParameterSet(QAction*, MeshModel&, RichParameterList& parameters) {
  plugin::add_parameters<float, RichParameterList, RichEnum, RichFloat, RichInt, RichBool>(parameters);
}

bool FilterLowStretchPlugin::fail(const std::string& message) {
  errorMessage = QString::fromStdString(message);
  Log(plugin::failure_line(message));
  return false;
}

bool FilterLowStretchPlugin::applyFilter(QAction*, MeshDocument& md, const RichParameterList& parameters,
                                         vcg::CallBackPos* cb) {
  if (md.mm() == nullptr) return fail("no mesh is loaded");
  MeshModel& m = *md.mm();

  const plugin::Run run = plugin::apply(m, parameters, cb, [this](const std::string& line) { Log(line); });
  if (!run.error.empty()) return fail(run.error);
  const QString texture = plugin::checkerboard_path();
  m.cm.textures.clear();  // every wedge now refers to texture 0
  if (texture.isEmpty())
    Log("note: checkerboard.png was not found next to the plugin; no texture attached");
  else
    m.cm.textures.push_back(texture.toStdString());
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterLowStretchPlugin)
