// @ts-check
// Panel `metals`: a dielectric and a conductor side by side (lecture, "Fresnel reflection and
// materials"). The metal's index is complex, n + ik, per RGB channel, so its F0 is high and
// coloured; its exact reflectance is compared with Schlick's on the channel's own F0, and near
// grazing the exact curve dips below F0, which Schlick cannot do, then rises to 1: a metal has a
// Fresnel factor too, and a note beside the panel says where the lecture's "almost no Fresnel
// factor" falls short (words.js).
import { cosDeg } from '../../optics/angles.js';
import { fresnelConductor, fresnelExact, normalIncidence } from '../../optics/fresnel.js';
import { metalById, metalF0, metals } from '../../optics/materials.js';
import { CHANNELS, metalCurveStats, metalCurves, schlickForF0 } from './physics.js';
import { createAudioTrace } from '../../ui/createAudioTrace.js';
import { angle, fixed } from '../../ui/format.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { createTwinStage } from '../shared/createTwinStage.js';
import { buildMetalsDom } from './buildMetalsDom.js';
import { NAMED_DIP, gapSource, metalsLectureGap } from './words.js';
import fragment from './metals.frag.glsl?raw';
import './styles.css';
import { schema } from './schema.js';
import { materialName } from '../shared/materialName.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/metals';
import { messages } from '../../i18n/messages.js';

export { schema };

const t = messages('metals', english);
const SUN = { azimuth: 35, elevation: 40 };
/** A channel's letter: R, G, B. */
const short = (channel) => t('short', { channel });
const CHANNEL_VARS = ['--c-red', '--c-green', '--c-blue'];

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = document.createElement('div');
  panel.className = 'mt-panel';
  root.append(panel);
  const uniforms = {
    uN: { value: 1.5 }, uMetalN: { value: [1, 1, 1] }, uMetalK: { value: [0, 0, 0] },
    uF0: { value: [0, 0, 0] }, uMethod: { value: 0 },
  };
  const stage = createTwinStage(panel, {
    fragment,
    uniforms,
    onFrame: ctx.frameDrawn,
    cache: { live: ['uN'] }, // the dielectric's index redraws its F alone (metals.frag.glsl)
    ariaLabel: t('stage'),
    fallback: t('noWebgl'),
  });
  stage.setLight(SUN.azimuth, SUN.elevation);

  const swatchMetals = metals.map((m) => ({ id: m.id, name: materialName(m.id), f0: metalF0(m) }));
  const dom = buildMetalsDom(panel, swatchMetals, (metalId) => ctx.set({ metal: metalId }));

  const plot = createLinePlot(dom.plotHost, {
    xLabel: t('xLabel'), yLabel: t('yLabel'), height: 340,
    // uPlot range function (createLinePlot passes yRange through): from the lowest curve's
    // tenth up to 1, so a dip of a few hundredths below a high F0 stays visible.
    yRange: (_u, min) => [Math.min(0.9, Math.floor((Number.isFinite(min) ? min : 0) * 10) / 10), 1],
    series: [
      ...CHANNELS.map((c, ch) => ({ label: t('seriesExact', { channel: short(c) }), stroke: CHANNEL_VARS[ch], width: 3 })),
      ...CHANNELS.map((c, ch) => ({ label: t('seriesSchlick', { channel: short(c) }), stroke: CHANNEL_VARS[ch], dash: [10, 7] })),
    ],
  });

  // Heard per channel: a metal has neither a Brewster nor a critical angle, its shallow dip is heard in the pitch.
  const trace = createAudioTrace(dom.plotHost, {
    plot,
    curves: () => {
      const metal = metalById(values.metal);
      const f0 = metalF0(metal);
      const name = materialName(metal.id);
      return [
        ...CHANNELS.map((c, ch) => ({
          label: t('traceExact', { metal: name, channel: short(c) }), at: (deg) => fresnelConductor(cosDeg(deg), metal.n[ch], metal.k[ch]),
        })),
        ...CHANNELS.map((c, ch) => ({
          label: t('traceSchlick', { metal: name, channel: short(c) }), at: (deg) => schlickForF0(cosDeg(deg), f0[ch]),
        })),
      ];
    },
    landmarks: () => ({ brewster: null, critical: null }),
  });

  ctx.bind(ctx.gui.addFolder(t('folder')), ['metal', 'fresnel', 'nT']);
  ctx.tie(dom.swatchControl, ['metal']);

  let curves = null;
  let stats = null;
  let curvesFor = '';
  function update() {
    const metal = metalById(values.metal);
    if (curvesFor !== metal.id) {
      curvesFor = metal.id;
      curves = metalCurves(metal);
      stats = metalCurveStats(curves, metal);
      plot.setData([curves.theta, ...curves.exact, ...curves.schlick]);
      // Where each channel's exact curve is lowest, when that is visibly below F0.
      plot.setMarks(stats.filter((s) => s.dip >= NAMED_DIP).map((s) => ({
        x: s.minimum.theta, color: CHANNEL_VARS[CHANNELS.indexOf(s.channel)],
        label: t('dipMark', { channel: short(s.channel), dip: fixed(s.dip, 3) }),
      })));
      dom.setTable(metal, stats);
      dom.setNote(metalsLectureGap(metal, stats), gapSource());
      trace.refresh();
    }
    const dielectricF0 = normalIncidence(1, values.nT);
    dom.setSwatches({ n: values.nT, f0: dielectricF0 }, metal.id);
    stage.setLabels([
      t('labelDielectric', { n: indexText(values.nT) }), t('labelMetal', { metal: materialName(metal.id), method: values.fresnel }),
    ]);
    if (!stage.view) return;
    uniforms.uN.value = values.nT;
    uniforms.uMetalN.value = [...metal.n];
    uniforms.uMetalK.value = [...metal.k];
    uniforms.uF0.value = [...curves.f0];
    uniforms.uMethod.value = values.fresnel === 'exact' ? 0 : 1;
    stage.render();
  }
  update();

  return {
    stage,
    view: stage.view,
    plot,
    get curves() { return curves; },
    get stats() { return stats; },
    update,
    describe() {
      const metal = metalById(values.metal);
      const list = (f) => {
        const [r, g, b] = stats.map(f);
        return t('rgb', { r, g, b });
      };
      const deepest = stats.reduce((a, b) => (b.dip > a.dip ? b : a));
      return t('describe', {
        metal: materialName(metal.id), f0: list((s) => fixed(s.f0, 3)), dielectricF0: fixed(normalIncidence(1, values.nT), 3),
        n: indexText(values.nT),
        errors: list((s) => t('valueAt', { value: fixed(s.maxError.value, 4), angle: angle(s.maxError.theta, 1) })),
        dips: deepest.dip > 0 ? 'yes' : 'no', channel: deepest.channel, dipValue: fixed(deepest.minimum.value, 4),
        dipAngle: angle(deepest.minimum.theta, 1), dip: fixed(deepest.dip, 4), method: values.fresnel,
      });
    },
    csv() {
      const columns = { theta_deg: curves.theta };
      CHANNELS.forEach((c, ch) => { columns[`exact_${c}`] = curves.exact[ch]; });
      CHANNELS.forEach((c, ch) => { columns[`schlick_${c}`] = curves.schlick[ch]; });
      CHANNELS.forEach((c, ch) => { columns[`abs_error_${c}`] = curves.error[ch]; });
      columns[`dielectric_n${values.nT}`] = curves.theta.map((t) => fresnelExact(cosDeg(t), 1, values.nT));
      return { filename: `metals-${values.metal}.csv`, columns };
    },
    png: stage.view ? () => stage.view.toDataURL() : null,
    trace,
    dispose() {
      trace.dispose();
      plot.dispose();
      stage.dispose();
    },
  };
}
