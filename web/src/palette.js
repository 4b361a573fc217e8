// Colours shared by the 2D views, the 3D view and the legends. Empty, interior and boundary
// cells are white, light blue-grey and black, as in the figures of the entity-slicing method.

export const CELL_RGB = {
  0: [255, 255, 255], // empty
  1: [183, 198, 216], // interior
  2: [255, 0, 255], // reserved code 10: never written, shown loudly if it appears
  3: [17, 17, 17], // boundary
};

export const CELL_CSS = {
  empty: '#ffffff',
  interior: '#b7c6d8',
  boundary: '#111111',
};

export const CANVAS_BACKGROUND = '#dde1e6';
export const CONTOUR = { outer: '#1c7ed6', hole: '#f76707', open: '#d6336c' };
export const HATCH = 'rgba(47, 158, 68, 0.85)';
export const DIFFERING = '#e03131';
export const SELECTED_LAYER = '#1c7ed6';
export const GRID_LINE = 'rgba(120, 130, 145, 0.55)';

export const MESH_FRONT = 0xc8c2b4; // sand
export const MESH_BACK = 0xe8590c; // inside-out facets
export const CELLS_INTERIOR = 0xc3cfdd;
export const CELLS_BOUNDARY = 0x2a2a2a;

export const DEFECT_COLOURS = {
  open_edges: 0xe03131,
  non_manifold_edges: 0xae3ec9,
  inconsistent_edges: 0xf08c00,
  degenerate_facets: 0xfab005,
  flipped_normals: 0x7048e8,
  self_intersections: 0xd6336c,
  non_manifold_vertices: 0x1098ad,
};
export const DEFECT_FALLBACK = 0x868e96;

export function hex(colour) {
  return `#${colour.toString(16).padStart(6, '0')}`;
}
