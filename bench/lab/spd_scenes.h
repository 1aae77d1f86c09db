#pragma once
// The seven scenes of Eric Haines' Standard Procedural Databases ("A Proposal for Standard
// Graphics Environments", IEEE CG&A 7(11), 1987), generated in memory from their published
// description as NFF text, the format the SPD writes, and read by rayo's NFF loader (so the
// scenes follow NFF's conventions exactly: docs/nff.md). Object counts at size n:
//   balls   Σ_{i=0..n} 9^i spheres (a sphereflake) and a floor square
//   gears   n³ gears of 36 teeth: 2 faces of 144 vertices and 144 side quads each; a floor square
//   mount   2·4^n triangles (a fractal mountain on a 2^n × 2^n grid) and 4 glass spheres
//   rings   6·Σ_{i=1..n} i² pentagonal rings of 5 cylinders and 5 spheres; a back wall
//   teapot  the Utah teapot's 32 patches cut into n×n quads, 64n² − 8n triangles (the 8 patches
//           that close in a point lose one triangle per column); a checkered floor of n² squares
//   tetra   4^n triangles (a Sierpinski tetrahedron of 4^(n−1) tetrahedra)
//   tree    2^(n+1) − 1 cones with a sphere at each top (a branching tree); a floor square
// Everything matches the SPD's files to their six printed digits, gears' colours and glass and
// mount's heights (the SPD's own hash and Gaussian numbers) included (docs/performance.md, "The
// SPD suite").
#include <string>
#include <vector>

#include "apps/scene/scene_description.h"

namespace rayo {

// balls gears mount rings teapot tetra tree, in that order.
const std::vector<std::string>& spd_scene_names();

// The largest size accepted for `name`, so that no scene exceeds about a million primitives.
int spd_max_size(const std::string& name);

// The SPD's default size of `name` (its generator's size_factor; the Readme's "Database
// Analysis" table is for these): balls 4, gears 4, mount 6, rings 7, teapot 12, tetra 6, tree 11.
int spd_default_size(const std::string& name);

// The NFF text of scene `name` at `size` (1..spd_max_size). Throws InputError naming the scene
// for an unknown name or a size out of range.
std::string spd_nff(const std::string& name, int size);

// spd_nff read by the NFF loader; source "spd:NAME:SIZE".
SceneDescription spd_scene(const std::string& name, int size);

}  // namespace rayo
