#include "filter_lowstretch.h"

#include "filter_lowstretch/plugin_common/lowstretch_filter.h"

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
  const plugin::Parameters& p = plugin::parameters();
  parameters.addParam(RichEnum(p.boundary.name, p.boundary.default_index, plugin::entries(p.boundary), p.boundary.label,
                               p.boundary.tooltip));
  parameters.addParam(RichFloat(p.exponent.name, float(p.exponent.default_value), p.exponent.label, p.exponent.tooltip));
  parameters.addParam(RichInt(p.max_passes.name, p.max_passes.default_value, p.max_passes.label, p.max_passes.tooltip));
  parameters.addParam(RichEnum(p.weights.name, p.weights.default_index, plugin::entries(p.weights), p.weights.label,
                               p.weights.tooltip));
  parameters.addParam(RichEnum(p.non_disk.name, p.non_disk.default_index, plugin::entries(p.non_disk), p.non_disk.label,
                               p.non_disk.tooltip));
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

  const plugin::Parameters& p = plugin::parameters();
  lowstretch::ChartOptions options;
  const lowstretch::Error invalid =
      plugin::make_options(parameters.getEnum(p.boundary.name), parameters.getEnum(p.weights.name),
                           parameters.getFloat(p.exponent.name), parameters.getInt(p.max_passes.name),
                           parameters.getEnum(p.non_disk.name), options);
  if (invalid) return fail(lowstretch::message(invalid));
  options.disk.progress = plugin::progress(cb);

  const plugin::Run run = plugin::run(m.cm, options, [this](const std::string& line) { Log(line); });
  if (!run.error.empty()) return fail(run.error);

  m.updateDataMask(plugin::written_data_mask<MeshModel>());
  plugin::write_result(m.cm, run);
  const QString texture = plugin::checkerboard_path();
  m.cm.textures.clear();  // every wedge now refers to texture 0
  if (texture.isEmpty())
    Log("note: checkerboard.png was not found next to the plugin; no texture attached");
  else
    m.cm.textures.push_back(texture.toStdString());
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterLowStretchPlugin)
