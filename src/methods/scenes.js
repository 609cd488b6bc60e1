// The scenes the advisor judges: each fixes a domain (which index pairs or metals, which angles,
// how the angles are weighted) and the precision the shader runs in. The ranges are the
// material classes each scene stands for; the indices are refractiveindex.info values (Polyanskiy,
// Scientific Data 11, 94 (2024)) at 589 nm, rounded: water 1.333 (Daimon & Masumura, Appl. Opt.
// 46, 3811 (2007)), ice 1.31 (Warren & Brandt, JGR 113, D14220 (2008)); metals from materials.json.
// A scene's label, its name inside a sentence (inText) and its note (its domain in words) are the
// catalogue's ("methods": scene.<id>, sceneInText.<id>, sceneNote.<id>), read when they are shown.
import english from 'virtual:messages/en/methods';
import { messages } from '../i18n/messages.js';
import { fresnelConductor, fresnelExact } from '../optics/fresnel.js';
import { linspace } from './errorMetrics.js';
import { metalById, metalF0 } from '../optics/materials.js';

// Cosine weighting (2 cosθ sinθ): the share of an object's pixels seen at view angle θ, right for
// an opaque object looked at from outside. Uniform θ for the "from inside" scenes: a viewer under
// water or inside a lens sees the surface at any angle, and the TIR band must not be weighted away.
const THETA_COUNT = 1801; // every 0.05°

const PLASTIC = linspace(1.3, 1.7, 9).map((n) => [1, n]); // air → plastic, paint, skin

/**
 * @param {string[]} ids
 */
function metalCases(ids) {
  return ids.flatMap((id) => {
    const metal = metalById(id);
    if (!metal) throw new RangeError(`no metal ${id} in materials.json`);
    const f0 = metalF0(metal);
    return metal.n.map((n, i) => [n, metal.k[i], f0[i]]); // 650, 550, 450 nm
  });
}

const t = messages('methods', english);

/**
 * A scene the advisor judges. cases: the argument lists after cos θ (nI, nT; or n, k, F0).
 * @typedef {{ id: string, kind: 'dielectric' | 'conductor', precision: 'fp32' | 'fp16', weighting: 'cosine' | 'uniform',
 *   cases: readonly (readonly number[])[] }} SceneProps
 */
/** @typedef {Readonly<SceneProps & { thetaCount: number, label: string, inText: string, note: string }>} Scene */

/**
 * @param {SceneProps} props
 * @returns {Scene}
 */
function scene(props) {
  const { id } = props;
  return Object.freeze({
    thetaCount: THETA_COUNT,
    ...props,
    cases: Object.freeze(props.cases.map((c) => Object.freeze(c))),
    get label() { return t(`scene.${id}`); },
    get inText() { return t(`sceneInText.${id}`); },
    get note() { return t(`sceneNote.${id}`); },
  });
}

export const SCENES = Object.freeze([
  scene({
    id: 'plastic',
    kind: 'dielectric',
    precision: 'fp32',
    weighting: 'cosine',
    cases: PLASTIC,
  }),
  scene({
    id: 'glass-inside',
    kind: 'dielectric',
    precision: 'fp32',
    weighting: 'uniform',
    cases: linspace(1.33, 1.5, 5).map((n) => [n, 1]),
  }),
  scene({
    id: 'ice-water',
    kind: 'dielectric',
    precision: 'fp32',
    weighting: 'uniform',
    cases: [[1.31, 1.333], [1.333, 1.31]],
  }),
  scene({
    id: 'metal',
    kind: 'conductor',
    precision: 'fp32',
    weighting: 'cosine',
    cases: metalCases(['gold', 'aluminium']),
  }),
  scene({
    id: 'phone-mediump',
    kind: 'dielectric',
    precision: 'fp16',
    weighting: 'cosine',
    cases: PLASTIC,
  }),
]);

/**
 * The scene with this id; throws on an unknown id.
 * @param {unknown} id
 */
export function sceneById(id) {
  const found = SCENES.find((s) => s.id === id);
  if (!found) throw new RangeError(`unknown scene ${String(id)}`);
  return found;
}

/**
 * The float64 reference for a kind: fresnelExact(cos, nI, nT) or fresnelConductor(cos, n, k).
 * @param {string} kind
 * @returns {(cos: number, ...args: number[]) => number}
 */
export function referenceFor(kind) {
  if (kind === 'dielectric') return fresnelExact;
  if (kind === 'conductor') return (cos, n, k) => fresnelConductor(cos, n, k);
  throw new RangeError(`kind must be 'dielectric' or 'conductor', got ${String(kind)}`);
}
