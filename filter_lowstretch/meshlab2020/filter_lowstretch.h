// MeshLab 2020.09 filter plugin "Low-stretch parameterization": plumbing between MeshLab's
// CMeshO and the core in filter_lowstretch/core (no algorithm here).
#pragma once
#include <QObject>

#include <common/interfaces.h>

class FilterLowStretchPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_LOW_STRETCH };

  FilterLowStretchPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  int getRequirements(QAction* action) override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  FILTER_ARITY filterArity(QAction* action) const override;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parameters) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                   vcg::CallBackPos* cb) override;

  // The MeshFilterInterface overloads taking a QAction stay visible next to the ones above.
  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;
  using MeshFilterInterface::initParameterSet;

 private:
  bool fail(const std::string& message);
};
