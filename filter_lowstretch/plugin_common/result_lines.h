// The lines that report a run to a person: the filter's log in MeshLab and the tool's output
// are the same lines. Plain C++ (no Qt), so the tool can print them too.
#pragma once
#include <string>
#include <vector>

#include "atlas/charts.h"

namespace lowstretch {

// printf into a std::string (at most 4096 bytes, as MeshLab's log).
std::string format(const char* f, ...) __attribute__((format(printf, 1, 2)));

// A disk: every pass (metrics, seconds, solver), the kept pass, the notes. Charts: each chart
// (the first 20), every pass over the whole mesh, the whole layout, the notes.
std::vector<std::string> result_lines(const ChartsResult& result);

}  // namespace lowstretch
