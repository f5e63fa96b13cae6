#include "plugin_common/option_table.h"

#include <cctype>
#include <sstream>

namespace lowstretch {

namespace {

std::vector<OptionRow> make_table() {
  return {
      {"boundary", "--boundary", "boundaryShape", "Boundary shape", OptionKind::Choice,
       {"square", "circle", "natural"}, {"Square", "Circle", "Natural"}, "", kToolAndFilter,
       "Where the boundary loop goes: the unit square (the paper's choice), the circle (strictly convex: no pass "
       "can flip a triangle), or the free boundary of a conformal map (least distortion at the boundary; flips "
       "are possible and are reported).",
       [](const ChartOptions& o) { return double(o.disk.boundary); },
       [](ChartOptions& o, double v) { o.disk.boundary = BoundaryShape(int(v)); }},
      {"exponent", "--exponent", "exponent", "Exponent", OptionKind::Real, {}, {}, "(0, 1]", kToolAndFilter,
       "eta: each pass divides the weights by the vertex stretch to the power eta. 1 is the paper's choice; "
       "smaller values redistribute the stretch more gently.",
       [](const ChartOptions& o) { return o.disk.exponent; }, [](ChartOptions& o, double v) { o.disk.exponent = v; }},
      {"max_passes", "--max-passes", "maxPasses", "Max passes", OptionKind::Whole, {}, {}, "0 to 1000", kToolAndFilter,
       "At most this many reweighting passes; the run stops earlier when the L2 stretch stops falling. 0 gives "
       "the initial map only, 1 gives U1.",
       [](const ChartOptions& o) { return double(o.disk.max_passes); },
       [](ChartOptions& o, double v) { o.disk.max_passes = int(v); }},
      {"weights", "--weights", "initialWeights", "Initial weights", OptionKind::Choice,
       {"floater", "meanvalue", "harmonic"}, {"Floater shape-preserving", "Mean value", "Harmonic"}, "",
       kToolAndFilter,
       "Weights of the initial map U0: Floater's shape-preserving weights (the paper's choice), mean value "
       "weights, or harmonic (cotangent) weights, which can be negative and are offered for comparison only.",
       [](const ChartOptions& o) { return double(o.disk.weights); },
       [](ChartOptions& o, double v) { o.disk.weights = InitialWeights(int(v)); }},
      {"non_disk", "--non-disk", "nonDisk", "Non-disk input", OptionKind::Choice, {"reject", "charts", "atlas"},
       {"Reject", "Make charts", "Atlas for any mesh"}, "", kToolAndFilter,
       "What to do with a mesh that is not a disk (holes, closed, handles, several parts, non-manifold edges or "
       "vertices): reject it with the reason, or make charts (the default): a low-stretch atlas whose charts "
       "stretch at most Max chart stretch, each on a rectangle, the rectangles tiling the texture a gutter apart. "
       "Charts keep a disk as the paper's single chart while that map has no flipped or zero-area triangle; "
       "atlas cuts a disk too when that uses the texture better. The mesh itself is never changed.",
       [](const ChartOptions& o) { return double(o.non_disk); },
       [](ChartOptions& o, double v) { o.non_disk = NonDisk(int(v)); }},
      {"max_stretch", "--max-stretch", "maxStretch", "Max chart stretch", OptionKind::Real, {}, {}, "at least 1",
       kToolAndFilter,
       "Charts: a chart whose L2 stretch is above this is cut in two. Lower gives less stretch, more charts and "
       "longer seams.",
       [](const ChartOptions& o) { return o.max_stretch; }, [](ChartOptions& o, double v) { o.max_stretch = v; }},
      {"fewer_seams", "--fewer-seams", "fewerSeams", "Fewer seams", OptionKind::Switch, {}, {}, "", kToolAndFilter,
       "Charts: merge more charts, for seams about as short as UVAtlas's: the atlas keeps a texture efficiency "
       "(coverage / L2^2) of 0.555 (or the unmerged atlas's, if lower) and 75% of the unmerged atlas's, instead of 0.61 "
       "and 90%, merged charts may keep a "
       "free boundary, packed by their outlines, and (up to 200,000 faces) every chart is refined as Refine stretch "
       "does, so charts stretch more and the atlas takes longer.",
       [](const ChartOptions& o) { return double(o.fewer_seams); }, [](ChartOptions& o, double v) { o.fewer_seams = v != 0; }},
      {"texture_size", "--texture-size", "textureSize", "Texture size", OptionKind::Whole, {}, {}, "8 to 65536",
       kToolAndFilter,
       "Side in texels of the texture the map is made for (the size you give Transfer: Vertex Color to "
       "Texture): the gutter is measured in its texels.",
       [](const ChartOptions& o) { return double(o.texture_size); },
       [](ChartOptions& o, double v) { o.texture_size = int(v); }},
      {"gutter", "--gutter", "gutter", "Gutter (texels)", OptionKind::Real, {}, {},
       "0.5 to an eighth of the texture size", kToolAndFilter,
       "Every texture coordinate stays this many texels inside the border of the texture, and charts this far "
       "apart, so that baking and mipmaps never address a texel outside it.",
       [](const ChartOptions& o) { return o.gutter; }, [](ChartOptions& o, double v) { o.gutter = v; }},
      {"repack", "--repack", "repackOnly", "Pack again only", OptionKind::Switch, {}, {}, "", kToolAndFilter,
       "Keep the mesh's atlas (its per-wedge texture coordinates, from an earlier run or a file) and only pack "
       "its charts again for Texture size and Gutter: each chart keeps its shape, turned by quarter turns and "
       "scaled to one texel density, packed by its outline; or the layout as it is, scaled onto the texture, "
       "where that keeps the gutter and uses the texture at least as well. Only a chart that overlaps itself or "
       "has no UV area is cut and mapped again, with the options for cutting and mapping.",
       [](const ChartOptions& o) { return double(o.repack); }, [](ChartOptions& o, double v) { o.repack = v != 0; }},
      {"refine", "--refine", "refineStretch", "Refine stretch", OptionKind::Switch, {}, {}, "", kToolAndFilter,
       "After the paper's passes, lower the L2 stretch further by minimizing it directly (projected Newton, "
       "no triangle flips; the boundary stays, but for an atlas's free charts), for at most 25 steps (the tool's "
       "--refine-iterations); an atlas's charts take 20 steps each. Steps are counted, never timed: every run gives the same map.",
       [](const ChartOptions& o) { return double(o.disk.refine); },
       [](ChartOptions& o, double v) { o.disk.refine = v != 0; }},
      {"refine_iterations", "--refine-iterations", "", "", OptionKind::Whole, {}, {}, "1 to 10000", kToolOnly,
       "Refine stretch: at most this many projected Newton steps on a single chart (it stops earlier when a step "
       "lowers the stretch energy by less than 1e-5 of it). More give less stretch and take longer.",
       [](const ChartOptions& o) { return double(o.disk.refine_iterations); },
       [](ChartOptions& o, double v) { o.disk.refine_iterations = int(v); }},
      {"max_charts", "--max-charts", "", "", OptionKind::Whole, {}, {}, "at least 1", kToolOnly,
       "Charts: at most this many; a chart the limit leaves uncut may stretch more than Max chart stretch.",
       [](const ChartOptions& o) { return double(o.max_charts); }, [](ChartOptions& o, double v) { o.max_charts = int(v); }},
      {"min_efficiency", "--min-efficiency", "", "", OptionKind::Real, {}, {}, "0 to 1", kToolOnly,
       "Charts: once cut, neighbouring charts are merged, those saving the most seam for the texture they cost "
       "first, while the atlas keeps this texture efficiency (coverage / L2^2) as finally laid out, each step packed "
       "by its outlines; 1 merges none. Lower gives shorter seams and more stretch. 0: at least 0.61 and 90% of the "
       "unmerged atlas's (0.555 and 75% with Fewer seams).",
       [](const ChartOptions& o) { return o.min_efficiency; }, [](ChartOptions& o, double v) { o.min_efficiency = v; }},
      {"solver", "--solver", "", "", OptionKind::Choice, {"amg", "direct"}, {}, "", kToolOnly,
       "How each pass is solved: algebraic multigrid with BiCGStab (the sparse LU from the pass where it does "
       "not converge on; an atlas's charts below 30,000 unknowns by the LU), or the sparse LU (KLU "
       "below 30,000 unknowns, UMFPACK above).",
       [](const ChartOptions& o) { return double(o.disk.solver.method); },
       [](ChartOptions& o, double v) { o.disk.solver.method = LinearSolver(int(v)); }},
      {"all_passes", "--all-passes", "", "", OptionKind::Switch, {}, {}, "", kToolOnly,
       "Run Max passes passes even when the stretch stops falling (benchmarks).",
       [](const ChartOptions& o) { return double(!o.disk.stop_when_stretch_rises); },
       [](ChartOptions& o, double v) { o.disk.stop_when_stretch_rises = v == 0; }},
  };
}

}  // namespace

const std::vector<OptionRow>& option_table() {
  static const std::vector<OptionRow> table = make_table();
  return table;
}

const OptionRow* option_named(const std::string& name) {
  for (const OptionRow& row : option_table())
    if (name == row.name) return &row;
  return nullptr;
}

std::string default_text(const OptionRow& row) { return value_text(row, ChartOptions()); }

std::string value_text(const OptionRow& row, const ChartOptions& options) {
  const double value = row.get(options);
  switch (row.kind) {
    case OptionKind::Choice: return row.words.at(size_t(value));
    case OptionKind::Switch: return value != 0 ? "on" : "off";
    default: {
      std::ostringstream text;
      text << value;
      return text.str();
    }
  }
}

std::string options_markdown() {
  std::ostringstream md;
  md << "| tool | MeshLab (script name) | pymeshlab | values | default | what it does |\n"
        "|---|---|---|---|---|---|\n";
  for (const OptionRow& row : option_table()) {
    std::string values = row.range;
    if (row.kind == OptionKind::Switch) values = "on, off";
    for (size_t i = 0; i < row.words.size(); ++i)
      values += (i ? ", " : "") + std::string(row.words[i]) +
                (row.entries.empty() ? "" : std::string(" (") + row.entries[i] + ")");
    std::string script = row.places == kToolAndFilter ? std::string(row.label) + " (`" + row.script_name + "`)" : "-";
    std::string python = "-";
    if (row.places == kToolAndFilter) {
      python = row.script_name;
      for (char& c : python) c = char(std::tolower(static_cast<unsigned char>(c)));
      python = "`" + python + "`";
    }
    md << "| `" << row.flag << "` | " << script << " | " << python << " | " << values << " | " << default_text(row)
       << " | " << row.help << " |\n";
  }
  return md.str();
}

}  // namespace lowstretch
