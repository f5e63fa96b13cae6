// Applies the "Low-stretch parameterization" filter to one mesh with MeshLab 2025.07's own library,
// headless, as pymeshlab does: PluginManager::loadPlugin (with its version, precision and plugin
// checks), a MeshDocument, vcglib's importers, initParameterList, applyFilter. Saves the mesh before
// and after the filter (also when the filter throws), so a test can check that a failing filter
// leaves the mesh as it was; the texture goes next to AFTER.ply.
//
// Usage: lowstretch_meshlab2025_runner PLUGIN.so INPUT BEFORE.ply AFTER.ply [name=value ...]
// (name=value sets a filter parameter: boundaryShape=1, exponent=0.5, ...; the pseudo-parameter
// deleteQualityAbove=Q first deletes, without compacting, every vertex of quality > Q and every face
// using one, as MeshLab's selection and delete filters leave a mesh). Prints
// "plugin: <filter name> | <python name> | <class>", "loaded has <V> vn <F> fn", the filter's log
// ("log: ..."), "output: <name>=<value>" per output value, "result: ok|failed",
// "message: <the MLException's text>", "dataMask before: 0x..." and "dataMask after: 0x...".
// Exit code 0 when the filter succeeded, 1 when it threw, 2 when the runner itself failed.
#include <QCoreApplication>
#include <QImage>
#include <QFileInfo>
#include <cstdio>

#include <common/mlexception.h>
#include <common/plugins/interfaces/filter_plugin.h>
#include <common/plugins/plugin_manager.h>
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

bool save(MeshModel& m, const char* path) {
  vcg::tri::io::PlyInfo info;
  info.mask = saveMask(m);
  if (vcg::tri::io::ExporterPLY<CMeshO>::Save(m.cm, path, true, info) != 0) return false;
  // MeshModel::saveTextures needs MeshLab's image IO plugins, which this runner does not load.
  const QString folder = QFileInfo(QString::fromLocal8Bit(path)).absolutePath();
  for (const auto& texture : m.getTextures())
    if (!texture.second.save(folder + "/" + QString::fromStdString(texture.first))) return false;
  return true;
}

// Deletes (marks deleted, keeps in the vectors) vertices of quality > q and the faces using them.
void deleteAbove(MeshModel& m, float q) {
  int faces = 0, vertices = 0;
  for (CFaceO& f : m.cm.face)
    if (!f.IsD() && (f.V(0)->Q() > q || f.V(1)->Q() > q || f.V(2)->Q() > q)) {
      vcg::tri::Allocator<CMeshO>::DeleteFace(m.cm, f);
      ++faces;
    }
  for (CVertexO& v : m.cm.vert)
    if (!v.IsD() && v.Q() > q) {
      vcg::tri::Allocator<CMeshO>::DeleteVertex(m.cm, v);
      ++vertices;
    }
  std::printf("deleted %d faces, %d vertices\n", faces, vertices);
}

int run(int argc, char** argv) {
  PluginManager plugins;
  MeshLabPlugin* loaded = plugins.loadPlugin(QString::fromLocal8Bit(argv[1]));  // throws MLException
  auto* filter = dynamic_cast<FilterPlugin*>(loaded);
  if (filter == nullptr || filter->actions().empty()) {
    std::fprintf(stderr, "%s is not a filter plugin\n", argv[1]);
    return 2;
  }
  QAction* action = filter->actions().front();
  std::printf("plugin: %s | %s | %d\n", qUtf8Printable(filter->filterName(action)),
              qUtf8Printable(filter->pythonFilterName(action)), int(filter->getClass(action)));

  MeshDocument md;
  MeshModel* m = md.addNewMesh(QString::fromLocal8Bit(argv[2]), "input");
  int loadMask = 0;
  vcg::tri::io::Importer<CMeshO>::LoadMask(argv[2], loadMask);
  m->enable(loadMask);
  const int readError = vcg::tri::io::Importer<CMeshO>::Open(m->cm, argv[2], loadMask);
  if (readError != 0 && vcg::tri::io::Importer<CMeshO>::ErrorCritical(readError)) {
    std::fprintf(stderr, "cannot read %s\n", argv[2]);
    return 2;
  }
  std::printf("loaded has %d vn %d fn\n", m->cm.vn, m->cm.fn);

  RichParameterList parameters = filter->initParameterList(action, md);
  for (int i = 5; i < argc; ++i) {
    const QStringList nameValue = QString(argv[i]).split('=');
    if (nameValue.size() == 2 && nameValue[0] == "deleteQualityAbove") {
      deleteAbove(*m, nameValue[1].toFloat());
      continue;
    }
    if (nameValue.size() != 2 || !parameters.hasParameter(nameValue[0])) {
      std::fprintf(stderr, "unknown parameter %s\n", argv[i]);
      return 2;
    }
    if (parameters.getParameterByName(nameValue[0]).value().isFloat())
      parameters.setValue(nameValue[0], FloatValue(nameValue[1].toFloat()));
    else  // RichInt and RichEnum both hold an IntValue
      parameters.setValue(nameValue[0], IntValue(nameValue[1].toInt()));
  }

  filter->setLog(&md.Log);
  m->updateDataMask(filter->getRequirements(action));  // as pymeshlab does
  const int maskBefore = m->dataMask();
  if (!save(*m, argv[3])) return 2;
  bool ok = true;
  QString message;
  std::map<std::string, QVariant> outputs;
  unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
  try {
    outputs = filter->applyFilter(action, parameters, md, postConditionMask, nullptr);
  } catch (const MLException& e) {
    ok = false;
    message = e.what();
  }
  const int maskAfter = m->dataMask();
  if (!save(*m, argv[4])) return 2;

  QStringList lines;
  md.Log.print(lines);
  for (const QString& line : lines) std::printf("log: %s\n", qUtf8Printable(line));
  for (const auto& output : outputs)
    std::printf("output: %s=%s (%s)\n", output.first.c_str(), qUtf8Printable(output.second.toString()),
                output.second.typeName());
  std::printf("result: %s\n", ok ? "ok" : "failed");
  std::printf("message: %s\n", qUtf8Printable(message));
  std::printf("dataMask before: 0x%08x\n", unsigned(maskBefore));
  std::printf("dataMask after: 0x%08x\n", unsigned(maskAfter));
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s PLUGIN.so INPUT BEFORE.ply AFTER.ply [name=value ...]\n", argv[0]);
    return 2;
  }
  QCoreApplication app(argc, argv);  // no display: Qt Core only, like pymeshlab
  try {
    return run(argc, argv);
  } catch (const MLException& e) {
    std::fprintf(stderr, "MeshLab error (loading %s, or reading or writing a mesh): %s\n", argv[1], e.what());
    return 2;
  }
}
