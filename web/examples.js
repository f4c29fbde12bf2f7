// The bundled example scenes offered by the submit form: scenes/cornell-box.json,
// scenes/cornell-glass.json and scenes/point-light-plane.json at 256x256 with 16 passes, so
// they finish quickly on a small machine (tests/web/examples.test.mjs holds them to those
// files). scenes/textured-mesh.json is left out: it needs asset files. Each entry:
// { name, title, scene }.

const quad = (origin, edgeU, edgeV, material, emission) => ({
  type: 'quad',
  origin,
  edge_u: edgeU,
  edge_v: edgeV,
  material,
  ...(emission ? { emission } : {}),
});

const sppm = (extra = {}) => ({
  integrator: 'sppm',
  passes: 16,
  photons_per_pass: 200000,
  initial_radius: 'auto',
  alpha: 0.6667,
  max_depth: 8,
  seed: 1,
  ...extra,
});

// The Cornell box both Cornell examples share: camera, wall materials, walls and light.
const cornellCamera = {
  type: 'perspective',
  position: [0, 1, 6.8],
  look_at: [0, 1, 0],
  up: [0, 1, 0],
  fov: 19.5,
  resolution: [256, 256],
};
const cornellMaterials = {
  white: { type: 'diffuse', albedo: [0.725, 0.71, 0.68] },
  red: { type: 'diffuse', albedo: [0.63, 0.065, 0.05] },
  green: { type: 'diffuse', albedo: [0.14, 0.45, 0.091] },
  light: { type: 'diffuse', albedo: [0.78, 0.78, 0.78] },
};
const cornellWallsAndLight = [
  quad([-1, 0, -1], [0, 0, 2], [2, 0, 0], 'white'),
  quad([-1, 2, -1], [2, 0, 0], [0, 0, 2], 'white'),
  quad([-1, 0, -1], [2, 0, 0], [0, 2, 0], 'white'),
  quad([-1, 0, -1], [0, 2, 0], [0, 0, 2], 'red'),
  quad([1, 0, -1], [0, 0, 2], [0, 2, 0], 'green'),
  quad([-0.235, 1.98, -0.19], [0.47, 0, 0], [0, 0, 0.38], 'light', [17, 12, 4]),
];

// A unit cube as a triangle mesh, scaled, turned about y and moved into place.
const block = (scale, angle, translate) => ({
  type: 'mesh',
  positions: [
    [-0.5, -0.5, -0.5],
    [0.5, -0.5, -0.5],
    [0.5, 0.5, -0.5],
    [-0.5, 0.5, -0.5],
    [-0.5, -0.5, 0.5],
    [0.5, -0.5, 0.5],
    [0.5, 0.5, 0.5],
    [-0.5, 0.5, 0.5],
  ],
  indices: [4, 5, 6, 4, 6, 7, 1, 0, 3, 1, 3, 2, 5, 1, 2, 5, 2, 6, 0, 4, 7, 0, 7, 3, 7, 6, 2, 7, 2, 3],
  material: 'white',
  transform: { scale, rotate: { axis: [0, 1, 0], angle }, translate },
});

export const EXAMPLES = [
  {
    name: 'cornell-box',
    title: 'Cornell box (diffuse)',
    scene: {
      camera: cornellCamera,
      materials: cornellMaterials,
      shapes: [
        ...cornellWallsAndLight,
        block([0.6, 0.6, 0.6], -17, [0.33, 0.3, 0.37]),
        block([0.6, 1.2, 0.6], 17, [-0.33, 0.6, -0.26]),
      ],
      render: sppm(),
    },
  },
  {
    name: 'cornell-glass',
    title: 'Cornell box with glass and mirror spheres',
    scene: {
      camera: cornellCamera,
      materials: {
        ...cornellMaterials,
        glass: { type: 'dielectric', ior: 1.5 },
        mirror: { type: 'mirror', reflectance: [0.95, 0.95, 0.95] },
      },
      shapes: [
        ...cornellWallsAndLight,
        { type: 'sphere', center: [0.42, 0.35, 0.35], radius: 0.35, material: 'glass' },
        { type: 'sphere', center: [-0.42, 0.35, -0.35], radius: 0.35, material: 'mirror' },
      ],
      render: sppm(),
    },
  },
  {
    name: 'point-light-plane',
    title: 'Point light over a plane',
    scene: {
      camera: {
        type: 'perspective',
        position: [0, 4, 0],
        look_at: [0, 0, 0],
        up: [0, 0, -1],
        fov: 60,
        resolution: [256, 256],
      },
      materials: { gray: { type: 'diffuse', albedo: [0.5, 0.5, 0.5] } },
      shapes: [quad([-10, 0, -10], [0, 0, 20], [20, 0, 0], 'gray')],
      lights: [{ type: 'point', position: [0, 1, 0], intensity: [10, 10, 10] }],
      render: sppm({ exposure: -1.5 }),
    },
  },
];

// A deep copy of the example's scene (shared parts included), or null for an unknown name.
export function exampleScene(name) {
  const example = EXAMPLES.find((e) => e.name === name);
  return example ? structuredClone(example.scene) : null;
}
