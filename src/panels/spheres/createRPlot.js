// The hero's R(θ) plot: exact, Schlick, Rs, Rp and the error, with the Brewster and critical
// angles marked (the range past the critical angle shaded) and an optional θ from a hovered pixel.
import { createLinePlot } from '../../ui/createLinePlot.js';
import { angle } from '../../ui/format.js';
import { brewsterMark, criticalMark, thetaMark } from '../../ui/plotMarks.js';
import english from 'virtual:messages/en/spheres';
import { messages } from '../../i18n/messages.js';

const t = messages('spheres', english);

/** The plot's curves, each named in the page's language. */
export const rSeries = () => [
  { label: t('exact'), stroke: '--c-exact', width: 3.5 },
  { label: t('schlick'), stroke: '--c-schlick', width: 3.5, dash: [12, 6] },
  { label: t('rs'), stroke: '--c-s', width: 2, dash: [3, 4] },
  { label: t('rp'), stroke: '--c-p', width: 2, dash: [10, 4, 3, 4] },
  { label: t('error'), stroke: '--c-error', width: 2.5 },
];

export function createRPlot(container) {
  const lines = createLinePlot(container, {
    xLabel: t('xLabel'), yLabel: t('yLabel'), series: rSeries(), height: 340,
  });
  let landmarks = { brewster: null, critical: null };
  let hover = null;
  const refresh = () => lines.setMarks([
    brewsterMark(landmarks.brewster),
    criticalMark(landmarks.critical),
    hover != null && thetaMark(hover, t('pixelMark', { theta: angle(hover, 1) })),
  ]);
  return {
    get plot() { return lines.plot; },
    setCurves(curves, next) {
      landmarks = next;
      lines.setData([curves.theta, curves.exact, curves.schlick, curves.s, curves.p, curves.error]);
      refresh();
    },
    setCursor: (deg, label) => lines.setCursor(deg, label),
    setHover(theta) {
      hover = theta;
      refresh();
    },
    dispose: () => lines.dispose(),
  };
}
