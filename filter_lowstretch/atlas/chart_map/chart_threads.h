// How the charts share the cores: a job per chart on the thread pool (core/thread_pool.h), largest
// charts first, and the solver options of a chart among those solved at once. A job's result
// depends on its chart alone, so an atlas is the same every run whatever the threads do.
#pragma once
#include <cstddef>
#include <vector>

#include "atlas/chart_map/solved_chart.h"
#include "core/parameterize.h"
#include "core/thread_pool.h"

namespace lowstretch {

// The indices of charts, most faces first (ties by index).
std::vector<int> largest_first(const std::vector<SolvedChart>& charts, size_t first, size_t end);

// The method's options for a chart of `faces` among `all_faces` solved at once. A chart with more
// than one thread's share of the faces solves u and v on two threads while the rest share the
// others (else it would finish last, alone on one); any other builds one multigrid hierarchy for
// u and v instead of two, the other charts keeping the threads busy.
Options for_share(Options options, size_t faces, size_t all_faces);

// The faces of charts [first, end) that are mapped (not cut ahead).
size_t faces_in(const std::vector<SolvedChart>& charts, size_t first, size_t end);

}  // namespace lowstretch
