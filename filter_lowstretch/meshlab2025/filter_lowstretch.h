// MeshLab 2022+ (FilterPlugin API; built and tested against MeshLab 2025.07 and pymeshlab 2025.7)
// filter plugin "Low-stretch parameterization": plumbing between MeshLab's CMeshO and the core in
// filter_lowstretch/core; what it shares with the MeshLab 2020.09 adapter is in plugin_common/.
#pragma once
#include <QObject>

#include <common/plugins/interfaces/filter_plugin.h>

class FilterLowStretchPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  enum { FP_LOW_STRETCH };

  FilterLowStretchPlugin();

  QString pluginName() const override;
  QString vendor() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  int getRequirements(const QAction* action) override;
  int getPreConditions(const QAction* action) const override;
  int postCondition(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;
  // Returns the metrics of the kept pass (pymeshlab hands them back as a dict); throws
  // MLException with the core's message, the mesh untouched, when the mesh is not a disk or a
  // parameter value is invalid.
  std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& parameters,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;

  // The FilterPlugin overloads taking a QAction or a MeshDocument stay visible next to the ones above.
  using FilterPlugin::filterInfo;
  using FilterPlugin::filterName;
  using FilterPlugin::initParameterList;
  using FilterPlugin::pythonFilterName;

 private:
  [[noreturn]] void fail(const std::string& message) const;
};
