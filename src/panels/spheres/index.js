// @ts-check
// Hero panel `spheres`: exact Fresnel vs Schlick on three spheres (exact, Schlick, error heatmap),
// one camera and light, with the live R(θ) plot below. Hovering a sphere marks that pixel's θ.
import { colormapGradient } from '../../ui/colormap.js';
import { angle as formatAngle, fixed } from '../../ui/format.js';
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { cosDeg, DEG } from '../../optics/angles.js';
import { fresnelExact, fresnelSchlick, brewsterAngle, criticalAngle, normalIncidence } from '../../optics/fresnel.js';
import { maxError, niceCeil, reflectanceCurves } from '../../optics/curves.js';
import { indexPresets } from '../shared/indexPresets.js';
import { addSwap } from '../shared/indexPair.js';
import { startWebGL } from '../shared/startWebGL.js';
import { createRPlot } from './createRPlot.js';
import { addDielectricTrace } from '../shared/dielectricTrace.js';
import { createSphereTrio } from './createSphereTrio.js';
import { buildSpheresDom } from './buildSpheresDom.js';
import { readByPointer } from '../../ui/readByPointer.js';
import { schema } from './schema.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/spheres';
import sharedWords from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

export { schema };

const t = messages('spheres', english);
const shared = messages('panelsShared', sharedWords);

const VIEW_KEYS = ['viewAz', 'viewEl', 'viewDist'];

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
const NARROW_PX = 820; // the width of the page or frame: phones, and tablets held upright

export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildSpheresDom(root);
  const plot = createRPlot(dom.plot);
  const trace = addDielectricTrace(dom.plot, plot, () => values, ['exact', 'schlick', 's', 'p']);
  const trio = startWebGL(dom.stage, () => createSphereTrio(dom.canvas, { onChange: onViewChange, onFrame: ctx.frameDrawn }),
    t('noWebgl'));

  // Controls: index presets (derived from the indices, so the URL holds only n), then the schema.
  const presets = indexPresets();
  const presetState = { matI: presets.idFor(values.nI), matT: presets.idFor(values.nT) };
  const optics = ctx.gui.addFolder(t('folderIndices'));
  const presetI = ctx.tie(optics.add(presetState, 'matI', presets.options).name(t('presetIncident'))
    .onChange((pid) => pid !== 'custom' && ctx.set({ nI: presets.index(pid) })), ['nI']);
  const presetT = ctx.tie(optics.add(presetState, 'matT', presets.options).name(t('presetSphere'))
    .onChange((pid) => pid !== 'custom' && ctx.set({ nT: presets.index(pid) })), ['nT']);
  ctx.bind(optics, ['nI', 'nT']);
  addSwap(ctx, optics, shared('swapLookOut'));
  ctx.bind(ctx.gui.addFolder(t('folderLook')), ['kd', 'ks', 'lightAz', 'lightEl', 'env', 'errScale']);
  ctx.bind(ctx.gui.addFolder(t('folderCamera')).close(), VIEW_KEYS);

  // Only the view keys that moved, so a deck's lock of one (say the distance) leaves the others
  // free; a refused change puts the camera back where the values say.
  function onViewChange(view) {
    const next = {
      viewAz: Math.round(view.azimuth * 10) / 10,
      viewEl: Math.round(view.elevation * 10) / 10,
      viewDist: Math.round(view.distance * 100) / 100,
    };
    const moved = Object.fromEntries(Object.entries(next).filter(([key, value]) => value !== values[key]));
    if (ctx.set(moved).refused) {
      trio.setView({ azimuth: values.viewAz, elevation: values.viewEl, distance: values.viewDist }, { silent: true });
    }
  }

  let curvesKey = '';
  let curves = null;
  let worst = null;
  let errScale = 0.05;

  function update() {
    const { nI, nT } = values;
    const key = `${nI}|${nT}`;
    if (key !== curvesKey) {
      curvesKey = key;
      curves = reflectanceCurves(nI, nT);
      worst = maxError(curves, nI, nT);
      const critical = criticalAngle(nI, nT);
      const brewster = brewsterAngle(nI, nT) / DEG;
      plot.setCurves(curves, { brewster, critical: critical === null ? null : critical / DEG });
      trace.refresh();
      dom.setSummary([
        [t('r0'), fixed(normalIncidence(nI, nT), 5)],
        [t('brewster'), formatAngle(brewster)],
        [t('critical'), critical === null ? t('noCritical') : formatAngle(critical / DEG)],
        [t('maxError'), t('valueAt', { value: fixed(worst.value, 4), angle: formatAngle(worst.theta) })],
      ]);
    }
    errScale = values.errScale === 'auto' ? niceCeil(worst.value) : Number(values.errScale);
    dom.setLegend(errScale, colormapGradient());
    presetState.matI = presets.idFor(nI);
    presetState.matT = presets.idFor(nT);
    presetI.updateDisplay();
    presetT.updateDisplay();
    if (!trio) return;
    const view = trio.view;
    if (view.azimuth !== values.viewAz || view.elevation !== values.viewEl || view.distance !== values.viewDist) {
      trio.setView({ azimuth: values.viewAz, elevation: values.viewEl, distance: values.viewDist }, { silent: true });
    }
    trio.setParams({
      nI, nT, kd: values.kd, ks: values.ks, envStrength: values.env, errScale,
      sunDir: directionFromAngles(values.lightAz, values.lightEl),
    });
  }

  // Hovering or tapping a sphere: its θ on the plot and the numbers at that pixel.
  const onHover = (event) => {
    const hit = trio?.pick(event.clientX, event.clientY);
    if (!hit) return onLeave();
    const theta = Math.acos(hit.cosTheta) / DEG;
    const exact = fresnelExact(hit.cosTheta, values.nI, values.nT);
    const schlick = fresnelSchlick(hit.cosTheta, values.nI, values.nT);
    dom.setReadout({ theta, exact, schlick, error: Math.abs(exact - schlick) });
    plot.setHover(theta);
  };
  const onLeave = () => {
    dom.setReadout(null);
    plot.setHover(null);
  };
  const stopReading = readByPointer(dom.canvas, onHover, onLeave);

  // On a phone or an upright tablet (or a frame as narrow) one sphere is shown at a time, picked
  // with the switch: three side by side would each be a thumbnail, the legend on the third.
  let chosen = 'exact';
  const narrow = window.matchMedia(`(max-width: ${NARROW_PX - 0.02}px)`);
  const showSingle = () => {
    const single = narrow.matches && trio ? chosen : null;
    dom.setSingle(single);
    trio?.setSingle(single);
  };
  const onSwitch = (event) => {
    chosen = event.currentTarget.dataset.mode;
    showSingle();
  };
  dom.switches.forEach((b) => b.addEventListener('click', onSwitch));
  narrow.addEventListener('change', showSingle);
  showSingle();
  update();

  return {
    trio,
    plot,
    trace,
    get curves() { return curves; },
    get errScale() { return errScale; },
    update,
    describe() {
      const at60 = fresnelExact(cosDeg(60), values.nI, values.nT);
      const s60 = fresnelSchlick(cosDeg(60), values.nI, values.nT);
      const critical = criticalAngle(values.nI, values.nT);
      return t('describe', {
        nI: indexText(values.nI), nT: indexText(values.nT), r0: fixed(normalIncidence(values.nI, values.nT), 4),
        exact60: fixed(at60, 4), schlick60: fixed(s60, 4),
        tir: critical === null ? 'no' : 'yes', critical: critical === null ? '' : formatAngle(critical / DEG),
        worst: fixed(worst.value, 4), worstAngle: formatAngle(worst.theta),
      });
    },
    csv() {
      const { theta, exact, schlick, s, p, error } = curves;
      return {
        filename: `fresnel-nI${values.nI}-nT${values.nT}.csv`,
        columns: { theta_deg: theta, R_exact: exact, R_schlick: schlick, Rs: s, Rp: p, abs_error: error },
      };
    },
    png: trio ? () => trio.toDataURL() : null,
    dispose() {
      narrow.removeEventListener('change', showSingle);
      stopReading();
      trio?.dispose();
      trace.dispose();
      plot.dispose();
    },
  };
}
