// Panel `normal-mips`: a bumpy plane receding to the horizon, its highlight shaded per pixel from
// the mip chain each technique stores (src/normals/), split-screen against a progressive,
// supersampled ground truth from the exact analytic normals, with an RMSE per technique.
import { WebGL2Unavailable } from '../gl/createRenderer.js';
import { buildAllChains } from '../normals/buildChain.js';
import { createNormalMap } from '../normals/createNormalMap.js';
import { exponentFromAlpha } from '../normals/lobeFormulas.js';
import { levelCount } from '../normals/momentPyramid.js';
import { sampleLevel0 } from '../normals/sampleLevel0.js';
import { TECHNIQUES } from '../normals/techniqueLayout.js';
import { normalIncidence } from '../optics/fresnel.js';
import { buildNormalMipsDom } from './normal-mipsDom.js';
import { createNormalMipsScene, SAMPLES_PER_FRAME } from './normal-mipsScene.js';
import { buildMipStrip } from './normal-mipsStrip.js';
import { buildInspector } from './normal-mipsInspector.js';
import './normal-mips.css';

export const id = 'normal-mips';
export const title = 'Mipmapping normal maps';
export const usesWebGL = true;
export const materialParam = null;
export const schema = {
  map: { type: 'enum', default: 'bumps', options: ['bumps', 'grooves', 'checker'], label: 'Normal map' },
  frequency: { type: 'number', default: 16, min: 2, max: 64, step: 2, label: 'Features per tile' },
  angle: { type: 'number', default: 35, min: 5, max: 60, step: 1, label: 'Slope angle ° (bump rim / facet)' },
  size: { type: 'enum', default: '256', options: ['128', '256', '512'], label: 'Texture size' },
  technique: { type: 'enum', default: 'toksvig', options: [...TECHNIQUES], label: 'Technique' },
  alpha: { type: 'number', default: 0.1, min: 0.02, max: 1, step: 0.005, label: 'Base roughness α (Beckmann)' },
  precision: { type: 'enum', default: 'f16', options: ['u8', 'f16', 'f32'], label: 'Storage precision' },
  channels: { type: 'enum', default: '3', options: ['3', '2'], label: 'Stored normal channels (2: z rebuilt)' },
  level: { type: 'number', default: -1, min: -1, max: 9, step: 1, label: 'Forced mip level (−1 = automatic)' },
  overlay: { type: 'boolean', default: false, label: 'Colour the mip level in use' },
  view: { type: 'enum', default: 'split', options: ['split', 'technique', 'truth', 'difference'], label: 'Picture' },
  viewEl: { type: 'number', default: 8, min: 2, max: 40, step: 0.5, label: 'View angle below horizon °' },
  lightEl: { type: 'number', default: 6, min: 1, max: 60, step: 0.5, label: 'Sun elevation °' },
  lightAz: { type: 'number', default: 0, min: -90, max: 90, step: 1, label: 'Sun azimuth ° (0 = ahead)' },
  fresnel: { type: 'enum', default: 'exact', options: ['exact', 'schlick', 'off'], label: 'Fresnel (n = 1.5)' },
  texelLevel: { type: 'number', default: 4, min: 0, max: 9, step: 1, label: 'Inspected level (or click the strip)' },
  texelX: { type: 'number', default: 0, min: 0, max: 511, step: 1, label: 'Inspected texel i' },
  texelY: { type: 'number', default: 0, min: 0, max: 511, step: 1, label: 'Inspected texel j' },
  truth: { type: 'boolean', default: true, label: 'Accumulate the ground truth' },
  truthSamples: { type: 'number', default: 128, min: 32, max: 2048, step: 16, label: 'Ground-truth samples per pixel' },
};

const DEG = Math.PI / 180;
const IOR = 1.5;
const MAP_KINDS = { bumps: 0, grooves: 1, checker: 2 };
const CHAIN_KEYS = ['map', 'frequency', 'angle', 'size', 'precision', 'channels'];
const SHIMMER_KEYS = [...CHAIN_KEYS, 'alpha', 'level', 'viewEl', 'lightEl', 'lightAz', 'fresnel'];
const INSPECT_KEYS = ['texelLevel', 'texelX', 'texelY'];
const TRUTH_KEYS = ['map', 'frequency', 'angle', 'alpha', 'viewEl', 'lightEl', 'lightAz', 'fresnel', 'truth', 'truthSamples'];

function mapParams({ map, frequency, angle }) {
  if (map === 'bumps') return { frequency, edgeAngleDeg: angle };
  if (map === 'grooves') return { frequency, angleDeg: angle, profile: 'v', direction: 'u' };
  return { frequency: 2 * Math.max(1, Math.round(frequency / 2)), angleDeg: angle }; // the checker tiles only with even counts
}

export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildNormalMipsDom(root);
  const strip = buildMipStrip(dom.root, {
    onPick(level, i, j) {
      Object.assign(values, { texelLevel: level, texelX: i, texelY: j });
      ctx.changed(INSPECT_KEYS);
    },
  });
  const inspector = buildInspector(dom.root);
  let stripStats = null;
  let inspected = null;
  let pyramid = null;
  let scene = null;
  let chains = null;
  let buildMs = 0;
  const size = () => Number(values.size);
  try {
    scene = createNormalMipsScene(dom.canvas, {
      onFrame: () => { ctx.frameDrawn(); showStatus(); },
      onConverged: () => ctx.changed([]), // re-describe with the error numbers
      uniforms: {
        uCamHeight: 1, uPitch: 0.1, uTanHalfFov: Math.tan(18 * DEG), uTile: 1, uLightPower: 5, uIor: IOR,
        uFresnel: 0, uKd: 0.05, uAlpha: 0.1, uForcedLevel: -1, uMapSize: 256, uMaxLevel: 8,
        uMapKind: 0, uMapFreq: 16, uMapAngle: 0.6, uGrooveProfile: 0, uSunDir: [0, 0.1, 1],
        uView: 0, uOverlay: 0, uDiffScale: 0.25,
      },
    });
  } catch (error) {
    if (!(error instanceof WebGL2Unavailable)) throw error;
    dom.showStageMessage(`${error.message} The receding plane needs WebGL2.`);
  }

  ctx.bind(ctx.gui.addFolder('Normal map'), ['map', 'frequency', 'angle', 'size']);
  ctx.bind(ctx.gui.addFolder('Technique'), ['technique', 'alpha', 'precision', 'channels', 'level', 'fresnel']);
  ctx.bind(ctx.gui.addFolder('Texel inspector').close(), INSPECT_KEYS);
  let shimmer = null;
  ctx.gui.add({ measure: () => { shimmer = scene?.measureShimmer() ?? null; dom.setShimmer(shimmer); ctx.changed([]); } }, 'measure')
    .name('Measure shimmer (all techniques)');
  ctx.bind(ctx.gui.addFolder('View and light'), ['view', 'overlay', 'viewEl', 'lightEl', 'lightAz', 'truth', 'truthSamples']);

  function rebuildChains() {
    const t0 = performance.now();
    const map = createNormalMap(values.map, mapParams(values));
    const normals = sampleLevel0(map, size());
    ({ chains, pyramid } = buildAllChains(normals, size(), { precision: values.precision, channels: Number(values.channels) }));
    buildMs = performance.now() - t0;
    scene?.setChains(chains);
  }

  function showStatus() {
    if (!scene) return;
    const { samples, cap, errors } = scene.state;
    const t = values.technique;
    const truth = values.truth ? `ground truth, ${samples} samples/pixel` : 'ground truth off';
    const names = { split: [t, truth], technique: [t, ''], truth: ['', truth] };
    const [left, right] = names[values.view] ?? [`|${t} − truth|`, truth];
    dom.setCaptions(left, right);
    dom.setErrors(errors, t, values.truth ? `Ground truth converging: ${samples} of ${cap} samples per pixel…`
      : 'Ground truth off: switch it on to compare techniques with numbers.');
  }

  function update(keys) {
    const changed = keys ? new Set(keys) : null;
    const has = (list) => !changed || list.some((k) => changed.has(k));
    if (has(CHAIN_KEYS) || !chains) rebuildChains();
    if (has(SHIMMER_KEYS)) shimmer = null;
    dom.setShimmer(shimmer);
    const levels = levelCount(size());
    const base = values.alpha;
    if (has([...CHAIN_KEYS, 'technique', 'alpha']) || !stripStats) {
      stripStats = strip.draw(chains, values.technique, base, { precision: values.precision, channels: Number(values.channels) });
    }
    if (has([...CHAIN_KEYS, ...INSPECT_KEYS, 'alpha']) || !inspected) {
      const level = Math.min(values.texelLevel, levels - 1);
      const last = (size() >> level) - 1;
      inspected = inspector.draw({
        pyramid, chains, level, i: Math.min(values.texelX, last), j: Math.min(values.texelY, last), alpha: base, mapKind: values.map,
      });
    }
    dom.setSummary(`${values.technique}, ${values.precision}, ${values.channels} channels; base α = ${base} `
      + `(Blinn-Phong s = ${exponentFromAlpha(base).toFixed(1)}); mip level ${values.level < 0 ? 'automatic' : `forced to ${Math.min(values.level, levels - 1)}`} `
      + `of 0–${levels - 1}; R0 = ${normalIncidence(1, IOR).toFixed(3)}; all six chains built in ${buildMs.toFixed(0)} ms.`
      + (values.precision === 'f32' && scene && !scene.floatLinear ? ' This GPU cannot filter 32-bit float textures: pick f16.' : ''));
    dom.setLegend(`level ${levels - 1} (difference: 0 to 0.25)`);
    if (!scene) return;
    const m = mapParams(values);
    scene.set({
      technique: values.technique,
      channels: Number(values.channels),
      cap: values.truthSamples,
      truthOn: values.truth,
      uAlpha: base,
      uForcedLevel: values.level < 0 ? -1 : Math.min(values.level, levels - 1),
      uMapSize: size(),
      uMaxLevel: levels - 1,
      uMapKind: MAP_KINDS[values.map],
      uMapFreq: m.frequency,
      uMapAngle: values.angle * DEG,
      uPitch: values.viewEl * DEG,
      uSunDir: [Math.sin(values.lightAz * DEG) * Math.cos(values.lightEl * DEG), Math.sin(values.lightEl * DEG),
        Math.cos(values.lightAz * DEG) * Math.cos(values.lightEl * DEG)],
      uFresnel: ['exact', 'schlick', 'off'].indexOf(values.fresnel),
      uView: values.truth ? ['split', 'technique', 'truth', 'difference'].indexOf(values.view) : 1,
      uOverlay: values.overlay ? 1 : 0,
    }, has(TRUTH_KEYS));
    // The truth does not depend on what the techniques store or on the forced level: only the errors do.
    if (!has(TRUTH_KEYS) && has(['size', 'precision', 'channels', 'level'])) scene.refreshErrors();
    showStatus();
  }
  update();

  return {
    get scene() { return scene; },
    get chains() { return chains; },
    get buildMs() { return buildMs; },
    get stripStats() { return stripStats; },
    get inspected() { return inspected; },
    get shimmer() { return shimmer; },
    samplesPerFrame: SAMPLES_PER_FRAME,
    update,
    describe() {
      const errors = scene?.state.errors;
      const level = values.level < 0 ? 'the automatic mip level' : `mip level ${values.level}`;
      const flicker = shimmer ? ` Shimmer of ${values.technique}: ${shimmer[values.technique].toFixed(4)} mean brightness change per pixel.` : '';
      const head = `${values.technique} on ${values.map} at base α = ${values.alpha}, using ${level}`;
      if (!values.truth) return `${head}; the ground truth is off, so there is no error number.${flicker}`;
      if (!errors) return `${head}; the ground truth is still converging (${scene?.state.samples ?? 0} samples per pixel).${flicker}`;
      const ranked = Object.entries(errors).sort((a, b) => a[1].rmse - b[1].rmse);
      return `${head}: RMSE against the ground truth ${errors[values.technique].rmse.toFixed(4)}; `
        + `best ${ranked[0][0]} (${ranked[0][1].rmse.toFixed(4)}), worst ${ranked.at(-1)[0]} (${ranked.at(-1)[1].rmse.toFixed(4)}).${flicker}`;
    },
    csv() {
      const errors = scene?.state.errors;
      if (!errors) return { filename: 'normal-mips-errors.csv', columns: { technique: [] } };
      const columns = { technique: [...TECHNIQUES], rmse: TECHNIQUES.map((t) => errors[t].rmse) };
      errors[TECHNIQUES[0]].bands.forEach((b) => {
        columns[`rmse_level_${b.level}`] = TECHNIQUES.map((t) => errors[t].bands[b.level].rmse);
      });
      return { filename: `normal-mips-${values.map}-errors.csv`, columns };
    },
    png: scene ? () => scene.toDataURL() : null,
    dispose() {
      scene?.dispose();
    },
  };
}
