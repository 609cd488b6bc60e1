// @ts-check
// Panel `reflect-refract`: a flat water or glass surface from a steep to a grazing view. Each
// pixel blends the reflected sky and the refracted pool floor by the exact Fresnel F at that
// pixel's angle (reflect-refract.frag.glsl); the numbers are for the centre ray.
import english from 'virtual:messages/en/reflect-refract';
import { messages } from '../../i18n/messages.js';
import { createShaderView } from '../../gl/createShaderView.js';
import { DEG } from '../../optics/angles.js';
import { normalIncidence } from '../../optics/fresnel.js';
import { dielectrics } from '../../optics/materials.js';
import { indexPresets } from '../shared/indexPresets.js';
import { angle, fixed, tickLabel } from '../../ui/format.js';
import { startWebGL } from '../shared/startWebGL.js';
import { centreRay, splitByElevation } from './physics.js';
import { bandLabel } from './words.js';
import { buildReflectRefractDom } from './buildReflectRefractDom.js';
import fragment from './reflect-refract.frag.glsl?raw';
import './styles.css';
import { schema } from './schema.js';

export { schema };

const t = messages('reflect-refract', english);

/** A control's value as a sentence writes it: the decimals of its step, in the page's language. */
const shown = (/** @type {string} */ key, /** @type {number} */ value) => tickLabel(value, /** @type {any} */ (schema)[key].step);

const LAYERS = { both: 0, reflected: 1, refracted: 2 };
// The scene: camera 6 tiles from the surface point under the centre of the view, 32° vertical
// field of view; cream and terracotta tiles (linear RGB), warm so that they never look like sky.
const CAMERA_DISTANCE = 6;
const FOV_DEG = 32;
export const TILE_COLOURS = Object.freeze({ a: [0.8, 0.62, 0.36], b: [0.45, 0.12, 0.05] });

// The lecture's round values first, then measured dielectrics at 589 nm (materials.json).
const presetList = () => [
  { id: 'water-lecture', name: t('preset.water'), n: 1.333 },
  { id: 'glass-lecture', name: t('preset.glass'), n: 1.5 },
  ...dielectrics.filter((m) => m.id !== 'air'),
];

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildReflectRefractDom(root);
  const view = startWebGL(dom.stage, () => createShaderView(dom.canvas, {
    fragment,
    // n, the depth, the layer and the floor redraw over the sky kept from the view (the .glsl file)
    cache: { live: ['uN', 'uDepth', 'uLayer', 'uTile', 'uTileA', 'uTileB'] },
    onFrame: ctx.frameDrawn,
    uniforms: {
      uElevation: { value: 0 },
      uDistance: { value: CAMERA_DISTANCE },
      uTanHalfFov: { value: Math.tan((FOV_DEG / 2) * DEG) },
      uN: { value: 1.333 },
      uDepth: { value: 1.5 },
      uTile: { value: 1 },
      uTileA: { value: [...TILE_COLOURS.a] },
      uTileB: { value: [...TILE_COLOURS.b] },
      uLayer: { value: 0 },
      uSunDir: { value: [0, 1, 0] }, // declared by <environment>; the sun itself is not drawn
    },
  }), t('noWebgl'));

  const presets = indexPresets(presetList());
  const presetState = { material: presets.idFor(values.nT) };
  ctx.bind(ctx.gui.addFolder(t('folder.view')), ['elevation']);
  const surface = ctx.gui.addFolder(t('folder.surface'));
  const preset = ctx.tie(surface.add(presetState, 'material', presets.options).name(t('material'))
    .onChange((pid) => pid !== 'custom' && ctx.set({ nT: presets.index(pid) })), ['nT']);
  ctx.bind(surface, ['nT', 'depth']);
  ctx.bind(ctx.gui.addFolder(t('folder.picture')), ['layer']);

  let ray = null;
  function update() {
    ray = centreRay(values.elevation, values.nT);
    dom.show(ray);
    dom.setNote(values.nT, normalIncidence(1, values.nT));
    presetState.material = presets.idFor(values.nT);
    preset.updateDisplay();
    if (!view) return;
    const u = view.uniforms;
    u.uElevation.value = values.elevation * DEG;
    u.uN.value = values.nT;
    u.uDepth.value = values.depth;
    u.uLayer.value = LAYERS[values.layer];
    view.render();
  }
  update();

  return {
    view,
    get ray() { return ray; },
    update,
    describe() {
      return t('describe', {
        elevation: angle(values.elevation, 1),
        nT: shown('nT', values.nT),
        theta: angle(ray.thetaDeg, 1),
        R: fixed(ray.R, 4),
        floor: fixed(ray.floorWeight, 4),
        T: fixed(ray.T, 4),
        thetaT: angle(ray.thetaTDeg),
        band: bandLabel(ray.band),
      });
    },
    csv() {
      const { elevation, R, T } = splitByElevation(values.nT);
      return {
        filename: `reflect-refract-nT${values.nT}.csv`,
        columns: { view_elevation_deg: elevation, theta_from_normal_deg: elevation.map((e) => 90 - e), R, T },
      };
    },
    png: view ? () => view.toDataURL() : null,
    dispose() {
      view?.dispose();
    },
  };
}
