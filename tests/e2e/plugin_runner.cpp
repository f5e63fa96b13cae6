// Applies the "Low-stretch parameterization" filter plugin to one mesh with MeshLab 2020.09's own
// library, as meshlabserver does, but saves the mesh before and after the filter even when the
// filter fails (meshlabserver exits without saving anything then). A test compares the two files
// to check that a failing filter leaves the mesh as it was.
//
// Usage: lowstretch_plugin_runner PLUGIN.so INPUT BEFORE.ply AFTER.ply [name=value ...]
// (name=value sets a filter parameter: boundaryShape=1, exponent=0.5, ...). Prints the filter's
// log, then "result: ok|failed", "errorMessage: ...", "dataMask before: 0x..." and
// "dataMask after: 0x...". The PLY files hold what the data masks say the mesh has.
//
// lowstretch_plugin_runner --list-filters PLUGIN_DIR prints "<class> <name>" for every filter of
// the plugins in PLUGIN_DIR: the GUI test finds where MeshLab puts ours in Filters > Texture.
#include <QApplication>
#include <QDir>
#include <QPluginLoader>
#include <cstdio>

#include <common/interfaces.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import.h>

namespace {

// The attributes the save mask takes from the data mask.
int saveMask(const MeshModel& m) {
  using vcg::tri::io::Mask;
  const std::pair<int, int> pairs[] = {
      {MeshModel::MM_VERTQUALITY, Mask::IOM_VERTQUALITY},   {MeshModel::MM_FACEQUALITY, Mask::IOM_FACEQUALITY},
      {MeshModel::MM_VERTTEXCOORD, Mask::IOM_VERTTEXCOORD}, {MeshModel::MM_WEDGTEXCOORD, Mask::IOM_WEDGTEXCOORD},
      {MeshModel::MM_VERTCOLOR, Mask::IOM_VERTCOLOR},       {MeshModel::MM_FACECOLOR, Mask::IOM_FACECOLOR},
      {MeshModel::MM_VERTRADIUS, Mask::IOM_VERTRADIUS},     {MeshModel::MM_WEDGCOLOR, Mask::IOM_WEDGCOLOR},
  };
  int mask = Mask::IOM_VERTCOORD | Mask::IOM_FACEINDEX;
  for (const auto& p : pairs)
    if (m.hasDataMask(p.first)) mask |= p.second;
  return mask;
}

int listFilters(const QString& dir) {
  for (const QFileInfo& file : QDir(dir).entryInfoList({"*.so"}, QDir::Files)) {
    QPluginLoader loader(file.absoluteFilePath());
    if (auto* filter = qobject_cast<MeshFilterInterface*>(loader.instance()))
      for (QAction* action : filter->actions())
        std::printf("%d %s\n", int(filter->getClass(action)), qUtf8Printable(action->text()));
  }
  return 0;
}

bool save(MeshModel& m, const char* path) {
  vcg::tri::io::PlyInfo info;
  info.mask = saveMask(m);
  return vcg::tri::io::ExporterPLY<CMeshO>::Save(m.cm, path, true, info) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && QString(argv[1]) == "--list-filters") {
    QApplication app(argc, argv);
    return listFilters(QString::fromLocal8Bit(argv[2]));
  }
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s PLUGIN.so INPUT BEFORE.ply AFTER.ply [name=value ...]\n"
                         "       %s --list-filters PLUGIN_DIR\n", argv[0], argv[0]);
    return 2;
  }
  QApplication app(argc, argv);  // the plugin makes QActions

  QPluginLoader loader(QString::fromLocal8Bit(argv[1]));
  auto* filter = qobject_cast<MeshFilterInterface*>(loader.instance());
  if (filter == nullptr) {
    std::fprintf(stderr, "cannot load the filter plugin %s: %s\n", argv[1], qUtf8Printable(loader.errorString()));
    return 2;
  }
  QAction* action = filter->actions().value(0);
  if (action == nullptr) return 2;

  MeshDocument md;
  MeshModel* m = md.addNewMesh(QString::fromLocal8Bit(argv[2]), "input");
  int loadMask = 0;
  vcg::tri::io::Importer<CMeshO>::LoadMask(argv[2], loadMask);
  m->Enable(loadMask);
  const int readError = vcg::tri::io::Importer<CMeshO>::Open(m->cm, argv[2], loadMask);
  if (readError != 0 && vcg::tri::io::Importer<CMeshO>::ErrorCritical(readError)) {
    std::fprintf(stderr, "cannot read %s\n", argv[2]);
    return 2;
  }

  RichParameterList parameters;
  filter->initParameterSet(action, md, parameters);
  for (int i = 5; i < argc; ++i) {
    const QStringList nameValue = QString(argv[i]).split('=');
    if (nameValue.size() != 2 || !parameters.hasParameter(nameValue[0])) {
      std::fprintf(stderr, "unknown parameter %s\n", argv[i]);
      return 2;
    }
    const Value& old = parameters.getParameterByName(nameValue[0]).value();
    if (old.isFloat())
      parameters.setValue(nameValue[0], FloatValue(nameValue[1].toFloat()));
    else if (old.isEnum())
      parameters.setValue(nameValue[0], EnumValue(nameValue[1].toInt()));
    else
      parameters.setValue(nameValue[0], IntValue(nameValue[1].toInt()));
  }

  GLLogStream log;
  filter->setLog(&log);
  m->updateDataMask(filter->getRequirements(action));  // as meshlabserver does
  const int maskBefore = m->dataMask();
  if (!save(*m, argv[3])) return 2;
  const bool ok = filter->applyFilter(action, md, parameters, nullptr);
  const int maskAfter = m->dataMask();
  if (!save(*m, argv[4])) return 2;

  QStringList lines;
  log.print(lines);
  for (const QString& line : lines) std::printf("log: %s\n", qUtf8Printable(line));
  std::printf("result: %s\n", ok ? "ok" : "failed");
  std::printf("errorMessage: %s\n", qUtf8Printable(filter->errorMsg()));
  std::printf("dataMask before: 0x%08x\n", unsigned(maskBefore));
  std::printf("dataMask after: 0x%08x\n", unsigned(maskAfter));
  return 0;
}
