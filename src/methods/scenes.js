// The scenes the advisor judges: each fixes a domain (which index pairs or metals, which angles,
// how the angles are weighted) and the precision the shader runs in. The ranges are the
// material classes each scene stands for; the indices are refractiveindex.info values (Polyanskiy,
// Scientific Data 11, 94 (2024)) at 589 nm, rounded: water 1.333 (Daimon & Masumura, Appl. Opt.
// 46, 3811 (2007)), ice 1.31 (Warren & Brandt, JGR 113, D14220 (2008)); metals from materials.json.
import { fresnelConductor, fresnelExact } from '../optics/fresnel.js';
import { linspace } from './errorMetrics.js';
import { metalById, metalF0 } from '../optics/materials.js';

// Cosine weighting (2 cosθ sinθ): the share of an object's pixels seen at view angle θ, right for
// an opaque object looked at from outside. Uniform θ for the "from inside" scenes: a viewer under
// water or inside a lens sees the surface at any angle, and the TIR band must not be weighted away.
const THETA_COUNT = 1801; // every 0.05°

const PLASTIC = linspace(1.3, 1.7, 9).map((n) => [1, n]); // air → plastic, paint, skin

function metalCases(ids) {
  return ids.flatMap((id) => {
    const metal = metalById(id);
    const f0 = metalF0(metal);
    return metal.n.map((n, i) => [n, metal.k[i], f0[i]]); // 650, 550, 450 nm
  });
}

function scene(props) {
  return Object.freeze({ thetaCount: THETA_COUNT, ...props, cases: Object.freeze(props.cases.map(Object.freeze)) });
}

export const SCENES = Object.freeze([
  scene({
    id: 'plastic',
    label: 'Opaque plastic seen from air',
    kind: 'dielectric',
    precision: 'fp32',
    weighting: 'cosine',
    cases: PLASTIC,
    note: 'air → n 1.3–1.7, external reflection only: no total internal reflection can occur.',
  }),
  scene({
    id: 'glass-inside',
    label: 'Glass or water seen from inside',
    kind: 'dielectric',
    precision: 'fp32',
    weighting: 'uniform',
    cases: linspace(1.33, 1.5, 5).map((n) => [n, 1]),
    note: 'n 1.33–1.5 → air: total internal reflection past 41.8°–48.8°.',
  }),
  scene({
    id: 'ice-water',
    label: 'Ice in water (nearly matched)',
    kind: 'dielectric',
    precision: 'fp32',
    weighting: 'uniform',
    cases: [[1.31, 1.333], [1.333, 1.31]],
    note: 'ice 1.31 ↔ water 1.333 both ways; R0 is 7.6e-5 and the critical angle from the water side is 79.3°.',
  }),
  scene({
    id: 'metal',
    label: 'A metal (gold, aluminium)',
    kind: 'conductor',
    precision: 'fp32',
    weighting: 'cosine',
    cases: metalCases(['gold', 'aluminium']),
    note: 'air → gold and aluminium, n + ik at 650, 550, 450 nm (materials.json).',
  }),
  scene({
    id: 'phone-mediump',
    label: 'Phone GPU with mediump (plastic)',
    kind: 'dielectric',
    precision: 'fp16',
    weighting: 'cosine',
    cases: PLASTIC,
    note: 'the plastic scene with every operation in float16, as on GPUs that run mediump at half precision.',
  }),
]);

/** The scene with this id; throws on an unknown id. */
export function sceneById(id) {
  const found = SCENES.find((s) => s.id === id);
  if (!found) throw new RangeError(`unknown scene ${String(id)}`);
  return found;
}

/** The float64 reference for a kind: fresnelExact(cos, nI, nT) or fresnelConductor(cos, n, k). */
export function referenceFor(kind) {
  if (kind === 'dielectric') return fresnelExact;
  if (kind === 'conductor') return (cos, n, k) => fresnelConductor(cos, n, k);
  throw new RangeError(`kind must be 'dielectric' or 'conductor', got ${String(kind)}`);
}
