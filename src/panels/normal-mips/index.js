// @ts-check
// Panel `normal-mips`: a bumpy plane receding to the horizon, its highlight shaded per pixel from
// the mip chain each technique stores (src/normals/), split-screen against a progressive,
// supersampled ground truth from the exact analytic normals, with an RMSE per technique.
import { createChainBuilder } from '../../normals/createChainBuilder.js';
import { createNormalMap } from '../../normals/createNormalMap.js';
import { mapUniforms } from '../../normals/mapUniforms.js';
import { exponentFromAlpha } from '../../normals/lobeFormulas.js';
import { levelCount } from '../../normals/momentPyramid.js';
import { TECHNIQUE_NAMES, TECHNIQUES } from '../../normals/techniqueLayout.js';
import { DEG } from '../../optics/angles.js';
import { normalIncidence } from '../../optics/fresnel.js';
import { optionLabel } from '../../host/params.js';
import { startWebGL } from '../shared/startWebGL.js';
import { benchChainBuild, watchLongTasks } from './benchChainBuild.js';
import { buildNormalMipsDom } from './buildNormalMipsDom.js';
import { createNormalMipsScene, SAMPLES_PER_FRAME } from './createNormalMipsScene.js';
import { createErrorDistancePlot } from './createErrorDistancePlot.js';
import { buildMipStrip } from './buildMipStrip.js';
import { buildInspector } from './buildInspector.js';
import './styles.css';
import { schema } from './schema.js';

export { schema };

const IOR = 1.5;
/** The maps as a sentence names them. */
const MAP_PHRASES = { bumps: 'bumps', grooves: 'V-grooves', checker: 'the slope checker', noise: 'value noise', mixed: 'the mixed map' };
const CHAIN_KEYS = ['map', 'frequency', 'angle', 'size', 'precision', 'channels'];
const LIGHT_KEYS = ['viewEl', 'lightEl', 'lightAz', 'lightDist'];
const SHIMMER_KEYS = [...CHAIN_KEYS, ...LIGHT_KEYS, 'alpha', 'level', 'anisotropy', 'fresnel'];
const INSPECT_KEYS = ['texelLevel', 'texelX', 'texelY'];
const TRUTH_KEYS = [...LIGHT_KEYS, 'map', 'frequency', 'angle', 'alpha', 'fresnel', 'truth', 'truthSamples'];
// Camera: height 1 above the plane, one tile per world unit (the scene's uCamHeight and uTile).
const CAM_HEIGHT = 1;

/**
 * The point light's world position: lightDist tiles from the view centre (where the middle of the
 * picture meets the plane) in the direction (azimuth, elevation); with azimuth 0 it is straight
 * ahead, so its mirror highlight runs towards the viewer. fromCamera: the unit direction to it
 * from the camera at (0, CAM_HEIGHT, 0).
 */
function lightPlacement({ viewEl, lightEl, lightAz, lightDist }) {
  const centre = [0, 0, CAM_HEIGHT / Math.tan(viewEl * DEG)];
  const dir = [Math.sin(lightAz * DEG) * Math.cos(lightEl * DEG), Math.sin(lightEl * DEG), Math.cos(lightAz * DEG) * Math.cos(lightEl * DEG)];
  const position = centre.map((c, k) => c + lightDist * dir[k]);
  const toLight = [position[0], position[1] - CAM_HEIGHT, position[2]];
  const length = Math.hypot(...toLight);
  return { position, fromCamera: toLight.map((c) => c / length) };
}

// Value noise: octave o adds a slope component of at most 3.75·amplitude·gain^o
// (createValueNoise.js), so over 3 octaves of gain ½ the steepest is 3.75·1.75·amplitude: the
// angle control sets that bound. Its base lattice is half the feature count, so the finest octave
// has twice as many cells as the control says.
const noiseAmplitude = (angleDeg) => Math.tan(angleDeg * DEG) / (3.75 * 1.75);

/** createNormalMap parameters for the controls (the GLSL twin gets the same via mapUniforms). */
function mapParams({ map, frequency, angle }) {
  if (map === 'bumps') return { frequency, edgeAngleDeg: angle };
  if (map === 'grooves') return { frequency, angleDeg: angle, profile: 'v', direction: 'u' };
  if (map === 'noise') return { frequency: Math.max(1, frequency / 2), amplitude: noiseAmplitude(angle) };
  if (map === 'mixed') {
    // 4 × 4 blocks; bumps and noise at blocks·f per tile, grooves at 2×, the checker at 4× that.
    return { blocks: 4, frequency: Math.max(1, Math.round(frequency / 8)), angleDeg: angle, edgeAngleDeg: angle, amplitude: noiseAmplitude(angle) };
  }
  return { frequency: 2 * Math.max(1, Math.round(frequency / 2)), angleDeg: angle }; // the checker tiles only with even counts
}

/** Keys still to apply after a build: undefined (none waiting) merged with keys (null: all). */
function mergeKeys(pending, keys) {
  if (pending === undefined) return keys ?? null;
  return pending === null || !keys ? null : [...pending, ...keys];
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildNormalMipsDom(root);
  const strip = buildMipStrip(dom.root, {
    onPick(level, i, j) {
      ctx.set({ texelLevel: level, texelX: i, texelY: j });
    },
  });
  const inspector = buildInspector(dom.root);
  const distancePlot = createErrorDistancePlot(dom.plotSlot);
  const builder = createChainBuilder();
  let stripStats = null;
  let inspected = null;
  let pyramid = null;
  let chains = null;
  let built = { ms: 0, where: builder.where, size: 0 };
  let deferred; // keys waiting for a chain build (null: all); undefined when none is running
  let buildDone = Promise.resolve();
  let disposed = false;
  const size = () => Number(values.size);
  const scene = startWebGL(dom.stage, () => createNormalMipsScene(dom.canvas, {
    onFrame: () => { ctx.frameDrawn(); showStatus(); },
    onConverged: () => ctx.invalidate(), // re-describe with the error numbers
    uniforms: {
      uCamHeight: CAM_HEIGHT, uPitch: 0.1, uTanHalfFov: Math.tan(18 * DEG), uTile: 1, uLightPower: 5, uIor: IOR,
      uFresnel: 0, uKd: 0.05, uAlpha: 0.1, uForcedLevel: -1, uMapSize: 256, uMaxLevel: 8, uAniso: 1,
      ...mapUniforms(createNormalMap(values.map, mapParams(values))), uSunDir: [0, 0.1, 1],
      uLightPos: [0, 3, 37], uLightDist2: 900, uView: 0, uOverlay: 0, uDiffScale: 0.25,
    },
  }), 'The receding plane needs WebGL2; the mip strip and the texel inspector below still work.');

  ctx.bind(ctx.gui.addFolder('Normal map'), ['map', 'frequency', 'angle', 'size']);
  ctx.bind(ctx.gui.addFolder('Technique'), ['technique', 'alpha', 'precision', 'channels', 'level', 'anisotropy', 'fresnel']);
  ctx.bind(ctx.gui.addFolder('Texel inspector').close(), INSPECT_KEYS);
  let shimmer = null;
  let shimmerRun = 0; // a change of settings makes a running measurement stale
  let shimmerBusy = false;
  let shimmerStopped = ''; // why the last measurement ended without numbers
  const measure = async () => {
    await whenBuilt(); // measure the chains of the current settings
    const run = ++shimmerRun;
    shimmerBusy = true;
    shimmerStopped = '';
    dom.setShimmer(null, true);
    const result = await scene?.measureShimmer() ?? null;
    if (run !== shimmerRun) return;
    shimmerBusy = false;
    shimmer = result;
    // null from a live scene: its context was lost under the read-backs
    if (result === null && scene && !disposed) {
      shimmerStopped = 'Shimmer meter: the measurement stopped because the graphics context was lost; press “Measure shimmer” again once the picture is back.';
    }
    dom.setShimmer(shimmer, false, shimmerStopped);
    ctx.invalidate();
  };
  ctx.gui.add({ measure }, 'measure').name('Measure shimmer (all techniques)');
  ctx.bind(ctx.gui.addFolder('View and light'), ['view', 'overlay', ...LIGHT_KEYS, 'truth', 'truthSamples']);

  // Chains are built off the page's thread (createChainBuilder); until the newest build arrives
  // the old picture stays and every other change waits, so picture, strip and truth always
  // belong to the same map.
  function rebuildChains(keys) {
    deferred = mergeKeys(deferred, keys);
    dom.setBusy(`Building the mip chains of a ${size()}² map…`);
    if (!chains) describeSettings();
    const request = { kind: values.map, params: mapParams(values), size: size(), precision: values.precision, channels: Number(values.channels) };
    buildDone = builder.build(request).then((result) => {
      if (!result || disposed) return;
      ({ chains, pyramid } = result);
      built = { ms: result.ms, where: result.where, size: request.size };
      scene?.setChains(chains, result.uploads);
      const keysNow = deferred;
      deferred = undefined;
      dom.setBusy('');
      apply(keysNow);
      ctx.invalidate(); // re-describe, now with this map
    }, (error) => {
      deferred = undefined;
      dom.setBusy(`Could not build the mip chains: ${error.message}`);
    });
  }

  async function whenBuilt() {
    for (let b; b !== buildDone;) {
      b = buildDone;
      await b;
    }
  }

  function showStatus() {
    if (!scene) return;
    const { samples, cap, errors } = scene.state;
    const t = values.technique;
    const name = TECHNIQUE_NAMES[t];
    const truth = values.truth ? `ground truth, ${samples} samples/pixel` : 'ground truth off';
    const names = { split: [name, truth], technique: [name, ''], truth: ['', truth] };
    const [left, right] = names[values.view] ?? [`|${name} − truth|`, truth];
    dom.setCaptions(left, right);
    distancePlot.show(errors, t);
    const pending = !values.truth ? 'Ground truth off: switch it on to compare techniques with numbers.'
      : samples < cap ? `Ground truth converging: ${samples} of ${cap} samples per pixel…`
        : 'Ground truth converged: measuring each technique against it…';
    dom.setErrors(errors, t, pending);
  }

  function update(keys) {
    const changed = keys ? new Set(keys) : null;
    if (!chains || !changed || CHAIN_KEYS.some((k) => changed.has(k))) rebuildChains(keys);
    else if (deferred !== undefined) deferred = mergeKeys(deferred, keys);
    else apply(keys);
  }

  // The line of key numbers and the legend; before the first chains arrive too, so that the panel
  // has its full height from its mount on.
  // The anisotropic taps in use: what was asked for, as far as this GPU offers them.
  const anisotropyInUse = () => (scene ? Math.min(Number(values.anisotropy), scene.maxAnisotropy) : 1);

  function describeSettings() {
    const levels = levelCount(size());
    const base = values.alpha;
    const aniso = anisotropyInUse();
    const anisoText = Number(values.anisotropy) === 1 ? 'trilinear' : `${aniso}× anisotropic filtering`
      + (aniso < Number(values.anisotropy) ? ` (this GPU offers at most ${scene.maxAnisotropy}×)` : '');
    dom.setSummary(`${TECHNIQUE_NAMES[values.technique]}, ${optionLabel(schema.precision, values.precision)}, ${values.channels} channels; base Beckmann α = ${base} `
      + `(Blinn-Phong s = ${exponentFromAlpha(base).toFixed(1)}); mip level ${values.level < 0 ? `automatic, ${anisoText}` : `forced to ${Math.min(values.level, levels - 1)}`} `
      + `of 0–${levels - 1}; R0 = ${normalIncidence(1, IOR).toFixed(3)}; ${built.size ? `all six chains of the ${built.size}² map built in ${built.ms.toFixed(0)} ms (${built.where})` : `the six chains of the ${size()}² map are being built`}.`
      + (values.precision === 'f32' && scene && !scene.floatLinear ? ' This GPU cannot filter 32-bit float textures: pick 16-bit float.' : '')
      + (builder.problem ? ` ${builder.problem}` : ''));
    dom.setLegend(`level ${levels - 1} (difference: 0 to 0.25)`);
  }

  function apply(keys) {
    const changed = keys ? new Set(keys) : null;
    const has = (list) => !changed || list.some((k) => changed.has(k));
    if (has(SHIMMER_KEYS)) {
      shimmer = null;
      shimmerRun += 1;
      shimmerBusy = false;
      shimmerStopped = '';
    }
    dom.setShimmer(shimmer, shimmerBusy, shimmerStopped);
    const levels = levelCount(size());
    const base = values.alpha;
    const channels = Number(values.channels);
    if (has([...CHAIN_KEYS, 'technique', 'alpha']) || !stripStats) {
      stripStats = strip.draw(chains, values.technique, base, { precision: values.precision, precisionName: optionLabel(schema.precision, values.precision), channels });
    }
    if (has([...CHAIN_KEYS, ...INSPECT_KEYS, 'alpha']) || !inspected) {
      const level = Math.min(values.texelLevel, levels - 1);
      const last = (size() >> level) - 1;
      inspected = inspector.draw({
        pyramid, chains, level, i: Math.min(values.texelX, last), j: Math.min(values.texelY, last), alpha: base, mapKind: values.map,
      });
    }
    describeSettings();
    if (!scene) return;
    if (changed?.size === 0) { // a re-describe (new errors, a finished build): nothing to draw
      showStatus();
      return;
    }
    const light = lightPlacement(values);
    scene.set({
      technique: values.technique,
      channels,
      cap: values.truthSamples,
      truthOn: values.truth,
      anisotropy: anisotropyInUse(),
      uAlpha: base,
      uForcedLevel: values.level < 0 ? -1 : Math.min(values.level, levels - 1),
      uMapSize: size(),
      uMaxLevel: levels - 1,
      ...mapUniforms(createNormalMap(values.map, mapParams(values))),
      uPitch: values.viewEl * DEG,
      uLightPos: light.position,
      uLightDist2: values.lightDist ** 2,
      uSunDir: light.fromCamera, // the sky draws its glow where the light is
      uFresnel: ['exact', 'schlick', 'off'].indexOf(values.fresnel),
      uView: values.truth ? ['split', 'technique', 'truth', 'difference'].indexOf(values.view) : 1,
      uOverlay: values.overlay ? 1 : 0,
    }, has(TRUTH_KEYS));
    // The truth does not depend on what the techniques store, the forced level or the filtering: only the errors do.
    if (!has(TRUTH_KEYS) && has(['size', 'precision', 'channels', 'level', 'anisotropy'])) scene.refreshErrors();
    showStatus();
  }
  update();

  return {
    get scene() { return scene; },
    get chains() { return chains; },
    get buildMs() { return built.ms; },
    /** Resolves once the newest chain build has been applied (tests, the benchmark). */
    whenBuilt,
    get stripStats() { return stripStats; },
    get inspected() { return inspected; },
    get shimmer() { return shimmer; },
    distancePlot,
    samplesPerFrame: SAMPLES_PER_FRAME,
    /**
     * npm run bench: the longest main-thread task while the ground truth accumulates to its cap
     * (the picture as it is now), chain-build timing at `size` (benchChainBuild), then the longest
     * task while this panel switches to that size and draws it (building, upload, strip).
     */
    async bench({ size = 1024, repeats = 5 } = {}) {
      // The panel's first build and first frame (the shader compiles there) are not part of it.
      await whenBuilt();
      await new Promise((resolve) => { requestAnimationFrame(() => requestAnimationFrame(resolve)); });
      const t0 = performance.now();
      const truth = await watchLongTasks(async () => {
        ctx.set({ truth: true });
        await new Promise((resolve) => {
          const poll = () => (scene?.state.errors || !scene ? resolve() : setTimeout(poll, 50));
          poll();
        });
      });
      const truthRun = { samples: scene?.state.samples ?? 0, ms: performance.now() - t0, longestTaskMs: truth.longestTaskMs };
      ctx.set({ truth: false });
      const build = await benchChainBuild({ size, repeats });
      const panel = await watchLongTasks(async () => {
        ctx.set({ size: String(size) });
        await whenBuilt();
        await new Promise((resolve) => { requestAnimationFrame(() => resolve()); });
      });
      return { ...build, panelLongestTaskMs: panel.longestTaskMs, truth: truthRun };
    },
    update,
    describe() {
      const errors = scene?.state.errors;
      const level = values.level < 0 ? 'the automatic mip level' : `mip level ${values.level}`;
      const name = TECHNIQUE_NAMES[values.technique];
      const flicker = shimmer ? ` Shimmer of ${name}: ${shimmer[values.technique].toFixed(4)} mean brightness change per pixel.` : '';
      const head = `${name} on ${MAP_PHRASES[values.map]} at base α = ${values.alpha}, using ${level}`;
      if (!values.truth) return `${head}; the ground truth is off, so there is no error number.${flicker}`;
      // The sample count is live in the caption; the description changes when the errors arrive.
      if (!errors) return `${head}; the ground truth is still converging, so there is no error number yet.${flicker}`;
      const ranked = Object.entries(errors).sort((a, b) => a[1].rmse - b[1].rmse);
      return `${head}: RMSE against the ground truth ${errors[values.technique].rmse.toFixed(4)}; `
        + `best ${TECHNIQUE_NAMES[ranked[0][0]]} (${ranked[0][1].rmse.toFixed(4)}), worst ${TECHNIQUE_NAMES[ranked.at(-1)[0]]} (${ranked.at(-1)[1].rmse.toFixed(4)}). `
        + `${distancePlot.note}${flicker}`;
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
      disposed = true;
      builder.dispose();
      inspector.dispose();
      distancePlot.dispose();
      scene?.dispose();
    },
  };
}
