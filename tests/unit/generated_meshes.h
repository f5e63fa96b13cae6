// Small meshes made in code, so that the tests need no files.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace testmesh {

struct Mesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
};

// An n x n grid over [0,1]^2, counter-clockwise, z = height(x, y); diagonals alternate.
Mesh grid(int n, const std::function<double(double, double)>& height = nullptr);
// The upper hemisphere of the unit sphere as a disk (rings x sectors, apex on top).
Mesh hemisphere(int rings, int sectors);
// hemisphere(rings, sectors) stretched along z (2.5) and x (1.5): Floater's map squeezes its top,
// as it does on the paper's heads, and the reweighting changes the weights strongly.
Mesh tall_cap(int rings, int sectors);
// A closed octahedron.
Mesh octahedron();
// Two copies of grid(n) side by side: two components.
Mesh two_grids(int n);
// A torus (closed, genus 1) of rings x sectors quads split into triangles.
Mesh torus(int rings, int sectors);
// A closed UV sphere: two poles and rings - 1 rings of `sectors` vertices.
Mesh sphere(int rings, int sectors);
// grid(n) with the faces whose centroid lies within `radius` of one of `centres` removed: a disk
// with punched holes (their vertices stay, unused).
Mesh punched_grid(int n, const std::vector<Eigen::RowVector2d>& centres, double radius);
// Two tori, each without one face, joined by a three-sided tube between the two holes: closed, genus 2.
Mesh double_torus();
// A band a triangle or two wide cut out of a wavy `columns` x 16 grid along its edges (the faces
// whose centroid lies within 0.4 of a wavy centre line; 28 faces for 8 columns): a jagged sliver
// with many ears, as the strips of a range scan leave; the vertices outside it stay, unused.
Mesh jagged_band(int columns);
// a's vertices and faces, then b's, b scaled by `scale` and moved by `offset`: one more component.
Mesh joined(const Mesh& a, const Mesh& b, double scale, const Eigen::RowVector3d& offset);
// m with `count` specks of scan debris after it: loose right triangles 0.01 on a side, in rows of
// `per_row` one unit apart, the first at (first_x, 0, 0).
Mesh with_specks(const Mesh& m, int count, int per_row, double first_x);
// m with each of `faces` (a, b, c) replaced by seven: a triangle of its shape `scale` times its
// size at its centroid, and the ring between the two; a merged scan's specks inside a surface.
Mesh with_tiny_triangles(const Mesh& m, const std::vector<int>& faces, double scale);
// The same faces, each with three vertices of its own at its corners' positions: a triangle
// soup, as STL files store a mesh.
Mesh soup(const Mesh& mesh);
// Removes face `face` from the mesh (makes a hole or opens a closed mesh).
Mesh without_face(const Mesh& mesh, int face);
// The closed unit cube [0,1]^3, each side an n x n grid of grid(n)'s faces, sides welded: faces
// 2 n^2 s .. 2 n^2 (s + 1) - 1 make side s.
Mesh cube(int n);
// A closed square plate: the top side (z = thickness) is grid(n) without the middle square of
// half its side (a hole of a quarter of its area), the first faces in grid order; then the bottom side, then one quad of wall per
// boundary edge. A flat face with a hole, as CAD parts have.
Mesh plate_with_hole(int n, double thickness);
// sphere(24, 32) with the side x > 0.5 pulled out into a long arm: one chart of it stretches a lot.
Mesh sphere_with_bump();
// A closed ball of 12,000 faces (sphere(64, 96)) with six arms: far above any bound, so that its
// largest parts are cut before they are mapped (ChartOptions::most_cuts_ahead).
Mesh ball_with_arms();

}  // namespace testmesh
