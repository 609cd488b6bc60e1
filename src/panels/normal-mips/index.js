// @ts-check
// Panel `normal-mips`: a bumpy plane receding to the horizon, its highlight shaded per pixel from
// the mip chain each technique stores (src/normals/), split-screen against a progressive,
// supersampled ground truth from the exact analytic normals, with an RMSE per technique. The view:
// the state and the runs are runs.js's, the words words.js's.
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { createChainBuilder } from '../../normals/createChainBuilder.js';
import { levelCount } from '../../normals/momentPyramid.js';
import { optionLabel } from '../controlText.js';
import { startWebGL } from '../shared/startWebGL.js';
import { benchChainBuild, watchLongTasks } from './benchChainBuild.js';
import { buildNormalMipsDom } from './buildNormalMipsDom.js';
import { createNormalMipsScene, SAMPLES_PER_FRAME } from './createNormalMipsScene.js';
import { createErrorDistancePlot } from './createErrorDistancePlot.js';
import { buildMipStrip } from './buildMipStrip.js';
import { buildInspector } from './buildInspector.js';
import { createNormalMipsRuns } from './runs.js';
import {
  busyText, chainProblemText, describeText, errorsCsv, legendText, shimmerStoppedText, statusText, summaryText,
} from './words.js';
import {
  CHAIN_KEYS, INSPECT_KEYS, initialUniforms, LIGHT_KEYS, touches,
} from './sceneSettings.js';
import './styles.css';
import { schema } from './schema.js';

export { schema };

const t = messages('normal-mips', english);

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
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
  let stripStats = null;
  let inspected = null;
  const scene = startWebGL(dom.stage, () => createNormalMipsScene(dom.canvas, {
    onFrame: () => { ctx.frameDrawn(); showStatus(); },
    onConverged: () => ctx.invalidate(), // re-describe with the error numbers
    onContextLost: () => runs.contextLost(),
    uniforms: initialUniforms(values),
  }), t('noWebgl'));

  const showShimmer = () => dom.setShimmer(runs.shimmer.result, runs.shimmer.busy, shimmerStoppedText(runs.shimmer.stopped));
  const runs = createNormalMipsRuns({
    values,
    builder: createChainBuilder(),
    scene,
    hooks: {
      applied: draw,
      busy: (state) => dom.setBusy(busyText(state)),
      summary: describeSettings,
      shimmer: showShimmer,
      invalidate: () => ctx.invalidate(),
    },
  });

  ctx.bind(ctx.gui.addFolder(t('folder.map')), ['map', 'frequency', 'angle', 'size']);
  ctx.bind(ctx.gui.addFolder(t('folder.technique')), ['technique', 'alpha', 'precision', 'channels', 'level', 'anisotropy', 'fresnel']);
  ctx.bind(ctx.gui.addFolder(t('folder.inspector')).close(), INSPECT_KEYS);
  ctx.gui.add({ measure: () => runs.measureShimmer() }, 'measure').name(t('measureShimmer'));
  ctx.bind(ctx.gui.addFolder(t('folder.viewLight')), ['view', 'overlay', ...LIGHT_KEYS, 'truth', 'truthSamples']);

  /** The captions, the error-by-distance plot and the error table, from the scene's progress. */
  function showStatus() {
    if (!scene) return;
    const { errors } = scene.state;
    const { left, right, pending } = statusText(values, scene.state);
    dom.setCaptions(left, right);
    distancePlot.show(errors, values.technique);
    dom.setErrors(errors, values.technique, pending);
  }

  /**
   * The line of key numbers and the legend; before the first chains arrive too, so that the panel
   * has its full height from its mount on.
   */
  function describeSettings() {
    dom.setSummary(summaryText(values, {
      built: runs.built,
      maxAnisotropy: scene ? scene.maxAnisotropy : null,
      floatLinear: scene ? scene.floatLinear : null,
      problem: chainProblemText(runs.problem),
    }));
    dom.setLegend(legendText(values));
  }

  /** Draws what changed once the runs applied the settings (keys: which; [] a re-describe; null all). */
  function draw(keys) {
    const has = touches(keys);
    showShimmer();
    const size = Number(values.size);
    const levels = levelCount(size);
    const { chains, pyramid } = runs;
    if (has([...CHAIN_KEYS, 'technique', 'alpha']) || !stripStats) {
      const precisionName = optionLabel('normal-mips', 'precision', values.precision);
      const storage = { precision: values.precision, precisionName, channels: Number(values.channels) };
      stripStats = strip.draw(chains, values.technique, values.alpha, storage);
    }
    if (has([...CHAIN_KEYS, ...INSPECT_KEYS, 'alpha']) || !inspected) {
      const level = Math.min(values.texelLevel, levels - 1);
      const last = (size >> level) - 1;
      inspected = inspector.draw({
        pyramid, chains, level, alpha: values.alpha, mapKind: values.map,
        i: Math.min(values.texelX, last), j: Math.min(values.texelY, last),
      });
    }
    describeSettings();
    showStatus();
  }

  runs.update();

  return {
    get scene() { return scene; },
    get chains() { return runs.chains; },
    get buildMs() { return runs.built.ms; },
    /** Resolves once the newest chain build has been applied (tests, the benchmark). */
    whenBuilt: runs.whenBuilt,
    get stripStats() { return stripStats; },
    get inspected() { return inspected; },
    get shimmer() { return runs.shimmer.result; },
    runs,
    distancePlot,
    samplesPerFrame: SAMPLES_PER_FRAME,
    /**
     * npm run bench: the longest main-thread task while the ground truth accumulates to its cap
     * (the picture as it is now), chain-build timing at `size` (benchChainBuild), then the longest
     * task while this panel switches to that size and draws it (building, upload, strip).
     */
    async bench({ size = 1024, repeats = 5 } = {}) {
      // The panel's first build and first frame (the shader compiles there) are not part of it.
      await runs.whenBuilt();
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
        await runs.whenBuilt();
        await new Promise((resolve) => { requestAnimationFrame(() => resolve()); });
      });
      return { ...build, panelLongestTaskMs: panel.longestTaskMs, truth: truthRun };
    },
    update: runs.update,
    describe: () => describeText(values, { errors: scene?.state.errors, shimmer: runs.shimmer.result, plotNote: distancePlot.note }),
    csv: () => errorsCsv(values, scene?.state.errors),
    png: scene ? () => scene.toDataURL() : null,
    dispose() {
      runs.dispose();
      inspector.dispose();
      distancePlot.dispose();
      scene?.dispose();
    },
  };
}
