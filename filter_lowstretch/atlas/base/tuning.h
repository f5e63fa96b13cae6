// The atlas's tuning: every number that was chosen by measuring, in one place, each with its
// reason. tests/bench/README.md gives the benchmarks that chose them.
#pragma once

namespace lowstretch {

// How a model made of faces is cut: the patches between edges sharper than `degrees`, cut by
// stretch to this share of the bound's excess over 1 (0.5: 1.2 -> 1.1).
struct FacesCut {
  double degrees, excess_kept;
};

struct AtlasTuning {
  // --- Cutting into charts (cut/, bound/) ---
  // Smaller charts cut coarse models better, at the cost of more seams and gutters.
  int smallest_chart = 15;
  // A chart of fewer than 2 x smallest_chart faces stays whole unless it stretches more than
  // small_cut_above times the bound and has smallest_cut_chart faces or more (a spike's tip or a
  // crease left in a small part can raise the L2 stretch of the whole atlas; cutting smaller charts
  // too would split a finely meshed CAD part into more charts than a tiling can hold), or has two
  // faces or more and stretches more than tiny_cut_above times the bound (a single triangle maps
  // without stretch).
  double small_cut_above = 2;
  int smallest_cut_chart = 8;  // faces
  double tiny_cut_above = 8;
  // Cuts ahead (a chart's largest part cut again before any part is mapped, once per doubling of
  // its L2 stretch over the bound): a chart far above the bound is mostly a body with protrusions,
  // which the cuts take off one at a time, and mapping the body after each would take most of the
  // time. None for a chart with flipped triangles, whose stretch says little, unless they are a few
  // slivers of a reconstruction (under few_invalid of its faces): then the others' stretch counts.
  double few_invalid = 1e-3;
  // Only parts this large are cut ahead: smaller ones are cheap to map, and cutting them unmapped
  // can change the atlas.
  int least_cut_ahead = 3000;  // faces
  // And only a body, a part that kept two thirds of the faces of the chart it was cut from: parts
  // cut nearer the middle may meet the bound, and cutting them unmapped makes a worse atlas.
  double least_body_share = 0.67;
  // Charts larger than this are cut without a deciding map: a scan's body of hundreds of thousands
  // of faces stretches far above any bound, and its map (multigrid that does not converge, then
  // the sparse LU) would take most of the time only to say so. Its leaves map it after all where
  // they cost more than the bound (the check of cuts ahead).
  int most_faces_to_decide = 20000;
  // Multigrid iterations for a deciding map before the sparse LU takes over: on a large body that
  // does not converge, every further iteration is time lost before the LU.
  int deciding_iterations = 20;
  // Only charts a little above the bound on their own rectangle get under it on the square; above
  // this, the chart is cut whatever its map, and its square would only cost a second solve.
  double square_may_meet = 1.5;
  // Pieces cut for validity with an L2 stretch this many times the bound are cut again.
  double piece_far_above = 2;
  // A UV triangle under this share of the texture is lost to every texture size and to rounding
  // (a 1024^2 texel is 1e-6 of it): a sliver of a reconstruction, mapped to scale.
  double least_uv_area = 1e-11;
  // MeshLab's ASCII PLY writer (both versions) and 2020.09's OBJ writer print texture coordinates
  // with 6 decimals: each moves by up to this much.
  double written_uv_rounding = 0.5e-6;
  // Rounds of cutting the charts with invalid faces and laying out again (what is left goes to
  // valid_as_stored).
  int most_repair_rounds = 3;
  // A face under the least UV area is a speck, not squashed, if its UV area over its 3D area is at
  // least this share of the layout's.
  double speck_density = 0.25;

  // --- Models made of faces (CAD parts) ---
  // Normals more than this apart make an edge sharp: a lower angle cuts curved faces into more
  // charts, a higher one leaves sharp edges uncut.
  double sharp_edge_degrees = 80;
  // The share of the area that the sharp edges must split off the parts' largest patches for the
  // model to be tried cut along them: CAD parts split off far more, statues far less (their sharp
  // edges are creases and spikes).
  double faces_share = 0.01;
  // The cuts tried: their faces are mostly flat, so more cuts leave charts that fill their
  // rectangles with little stretch; edges sharper than 30 degrees also part a large face from its
  // fillets, which stretch on a rectangle shared with it.
  FacesCut faces_cuts[3] = {{sharp_edge_degrees, 1}, {sharp_edge_degrees, 0.5}, {30, 0.5}};
  // The gentler cuts are tried only while the best atlas has a lower efficiency: they cost time
  // and do not improve an atlas that already uses the texture well.
  double gentler_cut_below = 0.7;
  // A face of such a model is mostly a plane, a cylinder or a fillet, which a free map keeps with
  // little stretch, so a free map need pay less than free_must_pay; which pays best depends on the
  // part, so both are laid out.
  double free_faces_must_pay[2] = {2, 1};

  // --- Mapping a chart (chart_map/) ---
  // A chart's passes are solved by the sparse LU below this many unknowns (the core's own bound
  // is SolverOptions::amg_minimum_rows): KLU factors a chart's system once and its later passes
  // reuse the pivots, where the multigrid builds its levels and iterates again every pass.
  int chart_amg_minimum_rows = 30000;
  // How much better a free map must use its box: the rectangle's further passes and the free
  // chart's cell, rarely of its shape, eat smaller gains.
  double free_must_pay = 4;
  // Packed by outline, a chart on its rectangle is tried free only above this L2 stretch: nearer
  // 1, its box packs better than its free outline (a CAD part's unmerged charts lose efficiency
  // when every chart is tried).
  double free_above = 1.02;
  // A chart seen along its normal at this L2 stretch or less is flat (a face of a CAD part).
  double flat_below = 1.02;
  // The turns tried within a quarter turn: the best is at most half a step (0.7 degrees) off the
  // turn of the smallest box, which for a 4 x 1 strip makes its box at most 5% larger.
  int projection_turns = 64;
  // The tips of a chart's boundary ears go a quarter of their chord out of the rectangle: a cut
  // along mesh edges leaves many ears, which a straight side squeezes to slivers that stretch.
  double ear_bulge = 0.25;
  // With fewer_seams (or refine), each map a layout keeps is refined (core/refine_stretch.h) this
  // many steps, however long they take, so that every run gives the same atlas. The maps that
  // decide cuts and merges are not: refining them too costs about as much time again, for no
  // shorter seam. Half as many steps leave some meshes of the atlas table below UVAtlas's
  // efficiency. Only on meshes of at most most_free_union_faces, as the free unions: every merge
  // step refines its charts again, which on a larger scan takes minutes.
  int refine_steps = 20;
  // The merge steps' layouts are judged on maps refined this many steps, and the kept one is laid
  // out again at refine_steps: most of a refinement's fall in stretch comes in its first steps.
  int judging_refine_steps = 8;
  // And no UV triangle shrinks below this share of its chart's map (or half its own area):
  // refining without it shrinks a scan's zero-area slivers past the texture (subtexel triangles,
  // which the repair rounds then cut into charts of their own). A disk's own refinement has none:
  // there such a floor stops the refinement early, at a higher stretch.
  double refine_least_area = 1e-6;

  // --- Packing (pack/) ---
  // How far from its own shape a chart may be stretched to fill its cell (width / height ratio);
  // a cell further off is filled only in part.
  double most_cell_mismatch = 2;
  // Below this share of empty texels, filling them gains too little to pay for another layout.
  double least_empty_share = 0.05;
  // A chart whose real faces cover this share of its box is seen as its box.
  double least_guest_fill = 0.9;
  // Charts mapped free where that stretches them less, turned to their smallest box, have packed
  // by outline to at most about nine tenths of the coverage the same charts reached on their
  // rectangles: they are freed and packed only where this share of that coverage would win.
  double most_free_outline_coverage = 0.92;
  // The grid of empty texels is the texture's texels up to this many per side, coarser beyond
  // (a 65536^2 grid would take 4 GiB).
  int most_grid_side = 2048;
  // Above this share of the texture in cells raised to the smallest a gutter allows, a note says so.
  double most_floored_share = 0.1;
  // Tries to put the guests into empty texels this many times, the guests without room going back
  // into the tiling each time (which makes every cell smaller, and so the room).
  int most_guest_rounds = 3;
  // Packing every chart by its outline: the density is bisected this many times (each step
  // narrows it to the square root of the ratio left: 2^(1/64), about 1%, after 6), after halving it
  // at most most_packing_halvings times from where the charts would cover the whole texture.
  int packing_bisections = 6;
  int most_packing_halvings = 12;

  // --- Merging charts for shorter seams (bound/merge_neighbours, search/merge_for_seams) ---
  // How far the charts' texture cost grows, step by step, as they are merged: each step is laid out
  // and measured. The first step that falls below the least efficiency is halved this many times
  // (a merge of two large charts can cost much more than the step's growth).
  double merge_growths[9] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 1, 2, 4};
  int merge_halvings = 3;
  // Free unions (fewer_seams, or a least efficiency given) are merged all the way, then the count
  // of merges bisected this many times: 2^7 steps resolve the last merges of a few hundred charts
  // to one or two. Only on meshes of at most most_free_union_faces: each step lays out every chart
  // fully mapped again, which on a larger scan takes several times the rest of the atlas; on the
  // scans below it, refined charts keep UVAtlas's efficiency, which unrefined ones do not.
  int merge_count_bisections = 7;
  int most_free_union_faces = 200000;
  // Steps that fall below the least efficiency, in a row, before merging stops: the rectangle
  // layout of a step can fall far (a cell of the wrong shape squeezes a chart) where the next
  // step's layout does not.
  int merge_misses = 1;
  // Unless options.min_efficiency is set, merged charts keep at least merge_floor and merge_keeps
  // of the unmerged atlas's efficiency (with its small charts in empty texels), by default and with
  // fewer_seams. The default's floor: at least the peers' efficiency on the atlas table's statues
  // and scans (tests/bench); its share: a CAD part's flat charts fill their boxes far better than
  // the peers', and merging them across its edges would give much of that away. Fewer seams: about
  // UVAtlas's efficiency (which has a third to a half of the default atlas's seams), the floor at
  // which it dominated UVAtlas on the most meshes of the table and the generated scans; a lower
  // one merged past UVAtlas's efficiency. An atlas already below its floor (debris in a tiling)
  // would merge nothing: fewer_seams keeps that atlas's efficiency instead; the default keeps its
  // floor, which a statue's charts would otherwise merge below.
  double merge_floor[2] = {0.61, 0.555};
  double merge_keeps[2] = {0.9, 0.75};
  // Merging maps unions of at most this many times the mesh's faces in all, or least_merge_work
  // faces if that is more, by default and with fewer_seams (or options.min_efficiency set): the
  // first merges, of small charts, save the most seam for their work; the last, of large ones,
  // cost the most time, which a small mesh can afford, and which fewer seams are worth.
  double merge_work[2] = {2, 8};
  double least_merge_work[2] = {200000, 800000};
  // Unions to merge are mapped this many at a time, on all threads: a few more maps than one at a
  // time would make, in less time.
  int merges_mapped_together = 8;

  // --- Choosing among atlases (search/) ---
  // An atlas this much more efficient than one chart per part could be skips laying that out.
  double clearly_better = 1.25;
};

constexpr AtlasTuning kTuning{};

}  // namespace lowstretch
