// @ts-check
// Panel `polarization`: Rs, Rp and their mean (the exact unpolarized R) against θ, with Brewster's
// angle (Rp = 0) and the critical angle marked, a readout at a chosen θ, and why a tool that shows
// only Rs reads high at oblique angles. Curves from curves.js; point values from fresnel.js.
import { brewsterAngle, criticalAngle, fresnelExact, fresnelPolarized } from '../../optics/fresnel.js';
import { cosDeg, DEG } from '../../optics/angles.js';
import { reflectanceCurves } from '../../optics/curves.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { angle, fixed } from '../../ui/format.js';
import { brewsterMark, criticalMark, thetaMark } from '../../ui/plotMarks.js';
import { addSwap } from '../shared/indexPair.js';
import './styles.css';
import { schema } from './schema.js';
import { addDielectricTrace } from '../shared/dielectricTrace.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/polarization';
import sharedWords from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

export { schema };

const t = messages('polarization', english);
const shared = messages('panelsShared', sharedWords);

/** The curves, named in the page's language. */
const series = () => [
  { label: t('seriesS'), stroke: '--c-s', width: 3 },
  { label: t('seriesP'), stroke: '--c-p', width: 3 },
  { label: t('seriesMean'), stroke: '--c-exact', width: 3.5, dash: [10, 6] },
];

/** Values at one angle: Rs, Rp (fresnelPolarized) and the unpolarized mean (fresnelExact). */
function at(thetaDeg, nI, nT) {
  const c = cosDeg(thetaDeg);
  const { s, p } = fresnelPolarized(c, nI, nT);
  return { s, p, mean: fresnelExact(c, nI, nT) };
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'polarization-panel');
  const summary = definitionList('pol-summary');
  const items = {
    brewster: summary.add(t('brewster')),
    atBrewster: summary.add(t('atBrewster')),
    critical: summary.add(t('critical')),
  };
  const plotHost = el('div', 'pol-plot');
  plotHost.setAttribute('role', 'img');
  plotHost.setAttribute('aria-label', t('plot'));
  const readout = el('p', 'pol-readout');
  readout.setAttribute('aria-live', 'polite');
  // Why an Rs-only reading is high: Rs ≥ Rp at every angle for a dielectric (|rp| = |rs|·
  // |cos(θ_i + θ_t)/cos(θ_i − θ_t)|, Hecht §4.6.2), so Rs is at least their mean; equal only head-on,
  // at grazing incidence and under total internal reflection.
  const note = el('p', 'pol-note', t('note'));
  const noteNumbers = el('strong', 'pol-note-numbers');
  note.append(noteNumbers);
  panel.append(summary.element, plotHost, readout, note);
  root.append(panel);

  const plot = createLinePlot(plotHost, {
    xLabel: t('xLabel'), yLabel: t('yLabel'),
    series: series(),
    height: 340,
  });
  // Rp first: its fall to zero is the Brewster angle, heard as the pitch reaching the bottom.
  const trace = addDielectricTrace(plotHost, plot, () => values, ['p', 's', 'exact']);

  const folder = ctx.gui.addFolder(t('folder'));
  ctx.bind(folder, ['nI', 'nT', 'theta']);
  ctx.tie(folder.add({ go: () => ctx.set({ theta: Math.round((brewsterAngle(values.nI, values.nT) / DEG) * 100) / 100 }) }, 'go')
    .name(t('readBrewster')), ['theta']);
  addSwap(ctx, folder, shared('swap'));

  let curves = null;
  let curvesKey = '';
  let point = null;
  let brewster = 0;
  let critical = null;

  function update() {
    const { nI, nT, theta } = values;
    const key = `${nI}|${nT}`;
    if (key !== curvesKey) {
      curvesKey = key;
      curves = reflectanceCurves(nI, nT);
      plot.setData([curves.theta, curves.s, curves.p, curves.exact]);
      trace.refresh();
      brewster = brewsterAngle(nI, nT) / DEG;
      const c = criticalAngle(nI, nT);
      critical = c === null ? null : c / DEG;
      const b = at(brewster, nI, nT);
      items.brewster.textContent = angle(brewster);
      items.atBrewster.textContent = t('atBrewsterValue', { p: fixed(b.p, 4), s: fixed(b.s, 4) });
      items.critical.textContent = critical === null ? t('noCritical') : angle(critical);
    }
    plot.setMarks([
      brewsterMark(brewster, t('brewsterMark')), criticalMark(critical), thetaMark(theta, t('thetaMark', { theta: angle(theta) })),
    ]);
    point = at(theta, nI, nT);
    readout.textContent = t('readout', { theta: angle(theta), s: fixed(point.s, 4), p: fixed(point.p, 4), mean: fixed(point.mean, 4) });
    noteNumbers.textContent = explain(point, theta, nI, nT);
  }

  /** The sentence with this angle's numbers. */
  function explain({ s, p, mean }, theta, nI, nT) {
    if (nI === nT) return t('matched');
    if (s - mean < 5e-5) {
      return t('agree', { theta: angle(theta), s: fixed(s, 4), mean: fixed(mean, 4), all: p > 0.9999 ? 'yes' : 'no' });
    }
    return t('tooHigh', { theta: angle(theta), s: fixed(s, 4), mean: fixed(mean, 4), ratio: fixed(s / mean, 2), p: fixed(p, 4) });
  }
  update();

  return {
    plot,
    get point() { return point; },
    update,
    describe() {
      const { nI, nT, theta } = values;
      return t('describe', {
        nI: indexText(nI), nT: indexText(nT), theta: angle(theta), s: fixed(point.s, 4), p: fixed(point.p, 4),
        mean: fixed(point.mean, 4), brewster: angle(brewster), tir: critical === null ? 'no' : 'yes',
        critical: critical === null ? '' : angle(critical),
      });
    },
    csv() {
      return {
        filename: `polarization-nI${values.nI}-nT${values.nT}.csv`,
        columns: { theta_deg: curves.theta, Rs: curves.s, Rp: curves.p, R_unpolarized: curves.exact },
      };
    },
    /** The plot on the panel's background (uPlot's canvas is transparent). */
    png: () => plot.toPng(),
    trace,
    dispose() {
      trace.dispose();
      plot.dispose();
      panel.remove();
    },
  };
}
