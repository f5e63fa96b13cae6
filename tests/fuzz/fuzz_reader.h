// Shared body of the reader fuzz targets: the input bytes become a file with the target's
// extension, which goes through the tool's path: read_mesh (picks the reader by extension),
// mesh_to_arrays, parameterize_charts (the default options, 2 passes: a disk's map, or charts of any
// other mesh) and, when that succeeds, write_parameterization.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

#include "atlas/charts.h"
#include "core/parameterize.h"
#include "tool/mesh_io.h"
#include "vcg_arrays/mesh_arrays.h"

namespace lowstretch_fuzz {

// One file per process (libFuzzer's -jobs/-fork workers are processes), removed at exit.
inline std::string& temp_file() {
  static std::string path;
  return path;
}
inline const std::string& temp_path(const char* extension) {
  std::string& path = temp_file();
  if (path.empty()) {
    const char* dir = std::getenv("TMPDIR");
    path = std::string(dir && *dir ? dir : "/tmp") + "/lowstretch_fuzz_" + std::to_string(getpid()) + "." + extension;
    std::atexit([] { std::remove(temp_file().c_str()); });
  }
  return path;
}

inline bool write_file(const std::string& path, const uint8_t* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && ok;
}

inline void read_and_parameterize(const char* extension, const uint8_t* data, size_t size) {
  const std::string& path = temp_path(extension);
  if (!write_file(path, data, size)) std::abort();  // the harness itself failed
  lowstretch::ToolMesh mesh;
  std::string error;
  if (!lowstretch::read_mesh(path, mesh, error)) {
    if (error.empty()) std::abort();  // a refusal must say why
    return;
  }
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const lowstretch::ArrayRows rows = lowstretch::mesh_to_arrays(mesh, V, F);
  lowstretch::ChartOptions options;
  options.disk.max_passes = 2;
  // A 256-texel texture: an atlas lays its charts out on the texture's texel grid some 30 times
  // (merge steps, small charts in empty texels, packing by outline), each pass over every texel; at
  // 1024 a 32-face input took 0.55 s, 25 s under the sanitizers, past the 10 s a hang is. The
  // fuzzer looks for crashes and hangs, which do not depend on the texture's size.
  options.texture_size = 256;
  const lowstretch::ChartsResult result = lowstretch::parameterize_charts(V, F, options);
  if (result.error) {
    if (lowstretch::message(result.error).empty()) std::abort();
    return;
  }
  if (result.corner_uv.rows() != F.rows() || result.face_stretch.size() != F.rows() ||
      (result.input_is_disk && result.disk_passes.empty()))
    std::abort();
  lowstretch::write_parameterization(mesh, rows, result);
}

}  // namespace lowstretch_fuzz
