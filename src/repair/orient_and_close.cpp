#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "diagnose/exact_geometry.hpp"
#include "repair/repair_internal.hpp"
#include "soup/orient_soup_visitor.hpp"
#include "soup/position_key.hpp"

namespace strata::repair::detail {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using soup::DoublesHash;
using soup::position_key;
using soup::PositionKey;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Face = Mesh::Face_index;
using Halfedge = Mesh::Halfedge_index;
using Vertex = Mesh::Vertex_index;
using Polygon = std::vector<std::size_t>;

/// Holes up to this many edges may fall back to CGAL's cubic search when the Delaunay search spaces
/// find no triangulation; larger ones would take minutes and stay open instead.
constexpr std::size_t kMaxCubicHoleEdges = 300;

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

Vec3 to_vec3(const Point& p) {
  // Epick points hold the doubles they were built from: exact.
  return {p.x(), p.y(), p.z()};
}

/// True when `corners` runs the triangle `reference` (same three positions) the other way round.
bool runs_reversed(const std::array<Vec3, 3>& corners, const std::array<Vec3, 3>& reference) {
  for (int r = 0; r < 3; ++r) {
    if (corners[0] == reference[r] && corners[1] == reference[(r + 1) % 3]) return false;
  }
  return true;
}

std::array<Vec3, 3> face_corners(const Mesh& mesh, Face f) {
  std::array<Vec3, 3> out;
  int k = 0;
  for (const Vertex v : mesh.vertices_around_face(mesh.halfedge(f))) {
    if (k < 3) out[k] = to_vec3(mesh.point(v));
    ++k;
  }
  STRATA_ASSERT(k == 3, "a face of the repaired mesh is not a triangle");
  return out;
}

std::array<Vec3, 3> clean_corners(const CleanSoup& clean, std::size_t i) {
  const auto& v = clean.facets[i].v;
  return {clean.vertices[v[0]], clean.vertices[v[1]], clean.vertices[v[2]]};
}

/// A kept facet's corners as the input gives them, or reversed by swapping the last two (so a facet
/// the repair does not turn is written exactly as it was read, starting corner included).
std::array<Vec3, 3> in_input_order(const std::array<Vec3, 3>& corners, bool flipped) {
  if (!flipped) return corners;
  return {corners[0], corners[2], corners[1]};
}

/// The facets as the soup stands, for when the oriented soup is not a polygon mesh.
std::vector<OutputFacet> soup_output(const std::vector<Point>& points,
                                     const std::vector<Polygon>& polygons, const CleanSoup& clean) {
  std::vector<OutputFacet> out(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    for (int k = 0; k < 3; ++k) out[i].corners[k] = to_vec3(points[polygons[i][k]]);
    out[i].clean_index = static_cast<std::int64_t>(i);
    out[i].flipped = runs_reversed(out[i].corners, clean_corners(clean, i));
    out[i].corners = in_input_order(clean_corners(clean, i), out[i].flipped);
  }
  return out;
}

/// Whether face i of `mesh` is polygon i of the soup it was built from, corner for corner.
bool faces_match_polygons(const Mesh& mesh, const std::vector<Polygon>& polygons) {
  if (mesh.number_of_faces() != polygons.size()) return false;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Face f(static_cast<Mesh::size_type>(i));
    std::vector<std::size_t> ids;
    for (const Vertex v : mesh.vertices_around_face(mesh.halfedge(f))) ids.push_back(v);
    if (ids.size() != polygons[i].size()) return false;
    const auto start = std::find(ids.begin(), ids.end(), polygons[i][0]);
    if (start == ids.end()) return false;
    std::rotate(ids.begin(), start, ids.end());
    if (ids != polygons[i]) return false;
  }
  return true;
}

/// Step 5b: in each connected shell, turn over the smaller set of facets (orient_polygon_soup keeps
/// the orientation of whichever facet it starts a shell from).
void keep_majority_orientation(Mesh& mesh, const CleanSoup& clean, RepairLog& log) {
  auto [cc, created] = mesh.add_property_map<Face, std::size_t>("f:repair_consistency_cc", 0);
  const std::size_t num_cc = PMP::connected_components(mesh, cc);
  std::vector<std::size_t> size(num_cc, 0);
  std::vector<std::size_t> reversed(num_cc, 0);
  std::vector<char> is_reversed(mesh.number_of_faces(), 0);
  for (const Face f : mesh.faces()) {
    is_reversed[f] = runs_reversed(face_corners(mesh, f), clean_corners(clean, f));
    ++size[cc[f]];
    reversed[cc[f]] += is_reversed[f];
  }
  std::vector<Face> turn;
  for (const Face f : mesh.faces()) {
    if (2 * reversed[cc[f]] > size[cc[f]]) {
      turn.push_back(f);
      is_reversed[f] = !is_reversed[f];
    }
  }
  if (!turn.empty()) PMP::reverse_face_orientations(turn, mesh);
  log.facets_flipped_for_consistency =
      static_cast<std::size_t>(std::count(is_reversed.begin(), is_reversed.end(), 1));
  mesh.remove_property_map(cc);
}

/// An undirected edge by its end positions (+0 and -0 alike), the smaller first.
using EdgePositions = std::array<double, 6>;

EdgePositions edge_positions(const Point& p, const Point& q) {
  std::array<double, 3> a{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
  std::array<double, 3> b{q.x() + 0.0, q.y() + 0.0, q.z() + 0.0};
  if (b < a) std::swap(a, b);
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}

using EdgeUses = std::unordered_map<EdgePositions, std::uint32_t, DoublesHash>;

/// How many faces use each edge, by position: copies of a vertex made by orient_polygon_soup are
/// the same point, so the edges of the facets around a cut non-manifold edge count together.
EdgeUses edge_uses(const Mesh& mesh) {
  EdgeUses uses;
  uses.reserve(mesh.number_of_edges());
  for (const Mesh::Edge_index e : mesh.edges()) {
    const Halfedge h = mesh.halfedge(e);
    const std::uint32_t faces =
        (mesh.is_border(h) ? 0 : 1) + (mesh.is_border(mesh.opposite(h)) ? 0 : 1);
    uses[edge_positions(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)))] += faces;
  }
  return uses;
}

/// The border cycles that are holes in the surface: every edge of the cycle is used by one facet
/// only. A cycle along an edge that other facets also use is where orient_polygon_soup cut a
/// non-manifold edge (or an edge between incompatibly oriented facets): the surface is not open
/// there, and filling it would wall off the other facets. Such cycles are counted apart.
std::vector<Halfedge> true_holes(const Mesh& mesh, EdgeUses& uses, RepairLog& log) {
  std::vector<Halfedge> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::vector<Halfedge> holes;
  for (const Halfedge h : cycles) {
    bool open = true;
    for (const Halfedge e : mesh.halfedges_around_face(h)) {
      open &= uses[edge_positions(mesh.point(mesh.source(e)), mesh.point(mesh.target(e)))] == 1;
    }
    if (open) {
      holes.push_back(h);
    } else {
      ++log.seams_at_shared_edges;
    }
  }
  return holes;
}

/// Step 7: triangulate every hole of at most max_hole_edges edges.
void fill_holes(Mesh& mesh, const RepairOptions& options, const std::vector<Halfedge>& holes,
                EdgeUses& uses, RepairLog& log) {
  std::unordered_set<PositionKey, DoublesHash> existing;
  existing.reserve(mesh.number_of_faces());
  for (const Face f : mesh.faces()) existing.insert(position_key(face_corners(mesh, f)));

  for (const Halfedge h : holes) {
    std::vector<EdgePositions> border;
    for (const Halfedge e : mesh.halfedges_around_face(h)) {
      border.push_back(edge_positions(mesh.point(mesh.source(e)), mesh.point(mesh.target(e))));
    }
    const std::size_t edges = border.size();
    if (edges > options.max_hole_edges) {
      ++log.holes_not_filled;
      continue;
    }
    std::vector<Face> patch;
    PMP::triangulate_hole(mesh, h, std::back_inserter(patch),
                          CGAL::parameters::use_2d_constrained_delaunay_triangulation(true)
                              .do_not_use_cubic_algorithm(edges > kMaxCubicHoleEdges));
    // CGAL promises no degenerate triangle; a patch that repeats a facet (the hole is the outline
    // of a single-sided sheet) would make a wall of zero thickness: refuse both.
    bool usable = !patch.empty();
    std::vector<PositionKey> keys;
    for (const Face f : patch) {
      const std::array<Vec3, 3> c = face_corners(mesh, f);
      const Point a(c[0].x, c[0].y, c[0].z), b(c[1].x, c[1].y, c[1].z), d(c[2].x, c[2].y, c[2].z);
      keys.push_back(position_key(c));
      if (CGAL::collinear(a, b, d) || existing.count(keys.back())) usable = false;
    }
    // A new edge of the patch that runs where an edge of the mesh already runs (a copy of a
    // vertex made the hole pass twice through one point) would make that edge non-manifold.
    std::vector<EdgePositions> chords;
    std::vector<Face> sorted_patch = patch;
    std::sort(sorted_patch.begin(), sorted_patch.end());
    for (const Face f : patch) {
      for (const Halfedge e : mesh.halfedges_around_face(mesh.halfedge(f))) {
        const Face other = mesh.face(mesh.opposite(e));
        const bool inner = std::binary_search(sorted_patch.begin(), sorted_patch.end(), other);
        if (!inner || e > mesh.opposite(e)) continue;
        chords.push_back(edge_positions(mesh.point(mesh.source(e)), mesh.point(mesh.target(e))));
        if (uses.count(chords.back()) > 0) usable = false;
      }
    }
    std::vector<EdgePositions> unique_chords = chords;  // a hole through one point twice
    std::sort(unique_chords.begin(), unique_chords.end());
    if (std::adjacent_find(unique_chords.begin(), unique_chords.end()) != unique_chords.end()) {
      usable = false;
    }
    std::vector<PositionKey> unique_keys = keys;
    std::sort(unique_keys.begin(), unique_keys.end());
    if (std::adjacent_find(unique_keys.begin(), unique_keys.end()) != unique_keys.end()) {
      usable = false;
    }
    if (!usable) {
      for (const Face f : patch) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
      ++log.holes_not_filled;
      continue;
    }
    existing.insert(keys.begin(), keys.end());
    for (const EdgePositions& chord : chords) uses[chord] += 2;
    for (const EdgePositions& edge : border) ++uses[edge];
    ++log.holes_filled;
    log.hole_facets_added += patch.size();
  }
}

/// Step 8: orient the closed shells so that they bound a volume.
void orient_closed_shells(Mesh& mesh, RepairLog& log) {
  auto [cc, created] = mesh.add_property_map<Face, std::size_t>("f:repair_volume_cc", 0);
  const std::size_t num_cc = PMP::connected_components(mesh, cc);
  std::vector<bool> closed(num_cc, true);
  for (const Halfedge h : mesh.halfedges()) {
    if (mesh.is_border(h)) closed[cc[mesh.face(mesh.opposite(h))]] = false;
  }
  log.closed_shells = static_cast<std::size_t>(std::count(closed.begin(), closed.end(), true));
  log.open_shells = num_cc - log.closed_shells;
  if (log.closed_shells == 0) {
    log.volume_orientation_note =
        num_cc == 0
            ? "skipped: no facet left"
            : fmt::format("skipped: no closed shell ({} open shell{}, which bound{} no volume)",
                          log.open_shells, log.open_shells == 1 ? "" : "s",
                          log.open_shells == 1 ? "s" : "");
    mesh.remove_property_map(cc);
    return;
  }

  // The closed shells as a mesh of their own (a vertex of a manifold mesh belongs to one shell).
  std::vector<std::size_t> sub_vertex(mesh.number_of_vertices() + mesh.number_of_removed_vertices(),
                                      kNone);
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  std::vector<Face> main_face;
  for (const Face f : mesh.faces()) {
    if (!closed[cc[f]]) continue;
    Polygon p;
    for (const Vertex v : mesh.vertices_around_face(mesh.halfedge(f))) {
      if (sub_vertex[v] == kNone) {
        sub_vertex[v] = points.size();
        points.push_back(mesh.point(v));
      }
      p.push_back(sub_vertex[v]);
    }
    polygons.push_back(std::move(p));
    main_face.push_back(f);
  }
  mesh.remove_property_map(cc);
  Mesh sub;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sub);
  if (!faces_match_polygons(sub, polygons)) {
    log.volume_orientation_note = "skipped: the closed shells do not form a polygon mesh";
    return;
  }

  auto sub_cc = sub.add_property_map<Face, std::size_t>("f:cc", 0).first;
  auto volume = sub.add_property_map<Face, std::size_t>("f:volume", 0).first;
  std::vector<std::size_t> nesting;
  std::vector<bool> outward;
  // With self-intersection tests, shells that cross each other are never taken as nested (two
  // overlapping solids are not a solid and its cavity).
  PMP::volume_connected_components(sub, volume,
                                   CGAL::parameters::face_connected_component_map(sub_cc)
                                       .nesting_levels(std::ref(nesting))
                                       .is_cc_outward_oriented(std::ref(outward))
                                       .do_orientation_tests(true)
                                       .do_self_intersection_tests(true));
  std::size_t num_shells = 0;
  for (const Face f : sub.faces()) num_shells = std::max(num_shells, sub_cc[f] + 1);

  // CGAL's outward test looks at the facets around the highest vertex, which is meaningless on a
  // shell that intersects itself (and CGAL leaves such shells untested). Those are found here
  // (CGAL's error codes do not say it reliably when the shells' orientations also disagree) and
  // judged by the sign of their exact volume instead: positive faces out.
  std::vector<bool> self_intersecting(num_shells, false);
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections(sub, std::back_inserter(pairs));
  for (const auto& [f, g] : pairs) {
    if (sub_cc[f] == sub_cc[g]) self_intersecting[sub_cc[f]] = true;
  }
  IndexedMesh exact;
  exact.vertices.reserve(points.size());
  for (const Point& p : points) exact.vertices.push_back(to_vec3(p));
  std::vector<std::uint32_t> group(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    exact.triangles.push_back({static_cast<VertexIndex>(polygons[i][0]),
                               static_cast<VertexIndex>(polygons[i][1]),
                               static_cast<VertexIndex>(polygons[i][2])});
    group[i] = static_cast<std::uint32_t>(sub_cc[Face(static_cast<Mesh::size_type>(i))]);
  }
  const std::vector<double> volumes =
      diagnose::detail::exact_signed_volumes(exact, group, num_shells).by_group_mm3;

  std::vector<bool> turn(num_shells, false);
  for (std::size_t s = 0; s < num_shells; ++s) {
    const bool reliable_test = outward.size() == num_shells && !self_intersecting[s];
    int facing = 0;  // +1 out, -1 in, 0 undecided
    if (reliable_test) {
      facing = outward[s] ? 1 : -1;
    } else if (volumes[s] != 0.0) {
      facing = volumes[s] > 0.0 ? 1 : -1;
    }
    const std::size_t level = s < nesting.size() ? nesting[s] : 0;
    const int wanted = level % 2 == 0 ? 1 : -1;
    if (facing != 0 && facing != wanted) {
      turn[s] = true;
      ++log.shells_reoriented;
    }
  }
  std::vector<Face> faces_to_turn;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (turn[sub_cc[Face(static_cast<Mesh::size_type>(i))]]) faces_to_turn.push_back(main_face[i]);
  }
  if (!faces_to_turn.empty()) PMP::reverse_face_orientations(faces_to_turn, mesh);
  log.facets_flipped_with_shells = faces_to_turn.size();
  log.volume_orientation_done = true;
  if (log.open_shells > 0) {
    log.volume_orientation_note =
        fmt::format("{} open shell{} left as oriented (an open shell bounds no volume)",
                    log.open_shells, log.open_shells == 1 ? "" : "s");
  }
}

}  // namespace

std::vector<OutputFacet> orient_and_close(const CleanSoup& clean, const RepairOptions& options,
                                          RepairLog& log) {
  log.fill_holes_requested = options.fill_holes;
  // The soup for CGAL: only the vertices the facets use (an isolated vertex has no halfedge).
  std::vector<std::size_t> index(clean.vertices.size(), kNone);
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  polygons.reserve(clean.facets.size());
  for (const WorkFacet& f : clean.facets) {
    Polygon p(3);
    for (int k = 0; k < 3; ++k) {
      if (index[f.v[k]] == kNone) {
        index[f.v[k]] = points.size();
        const Vec3& v = clean.vertices[f.v[k]];
        points.emplace_back(v.x, v.y, v.z);
      }
      p[k] = index[f.v[k]];
    }
    polygons.push_back(std::move(p));
  }
  if (polygons.empty()) {
    log.volume_orientation_note = "skipped: no facet left";
    return {};
  }

  const soup::OrientSoupCounts counters = soup::orient_soup(points, polygons);
  log.vertex_copies_added = counters.points_added;
  log.non_manifold_vertices_split = counters.non_manifold_vertices.size();
  log.non_manifold_edges = counters.non_manifold_edges.size();

  Mesh mesh;
  if (PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  }
  if (!faces_match_polygons(mesh, polygons)) {
    std::vector<OutputFacet> out = soup_output(points, polygons, clean);
    log.facets_flipped_for_consistency = static_cast<std::size_t>(
        std::count_if(out.begin(), out.end(), [](const OutputFacet& f) { return f.flipped; }));
    log.volume_orientation_note = "skipped: the oriented facets do not form a polygon mesh";
    return out;
  }
  log.polygon_mesh = true;
  keep_majority_orientation(mesh, clean, log);

  log.borders_stitched = PMP::stitch_borders(mesh);
  // Stitching removes vertices and hole filling may take a patch back: compact the mesh so that
  // CGAL's index maps (sized by the number of elements) match the indices. Removed faces are never
  // input faces, so the input faces keep their indices.
  mesh.collect_garbage();

  EdgeUses uses = edge_uses(mesh);
  std::vector<Halfedge> holes = true_holes(mesh, uses, log);
  log.holes_found = holes.size();
  if (options.fill_holes) {
    fill_holes(mesh, options, holes, uses, log);
    mesh.collect_garbage();
  }

  orient_closed_shells(mesh, log);

  std::vector<OutputFacet> out;
  out.reserve(mesh.number_of_faces());
  std::vector<Face> faces(mesh.faces().begin(), mesh.faces().end());
  std::sort(faces.begin(), faces.end());
  for (const Face f : faces) {
    OutputFacet o;
    o.corners = face_corners(mesh, f);
    if (static_cast<std::size_t>(f) < clean.facets.size()) {
      o.clean_index = static_cast<std::int64_t>(f);
      o.flipped = runs_reversed(o.corners, clean_corners(clean, f));
      o.corners = in_input_order(clean_corners(clean, f), o.flipped);
    }
    out.push_back(o);
  }
  return out;
}

}  // namespace strata::repair::detail
