// Error against distance in the normal-mips panel: each technique's RMSE against the ground truth
// per mip-level band λ (the level the hardware samples grows with distance, one step per doubling
// of the footprint), from the same numbers as the error table. Where naive and renormalized climb
// and the variance-keeping techniques stay low is where a distant bumpy surface turns too shiny.
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { el } from '../../ui/el.js';
import { TECHNIQUES } from '../../normals/techniqueLayout.js';
import { TECHNIQUE_STYLES } from './techniqueStyles.js';
import { techniqueName } from './techniqueName.js';

const t = messages('normal-mips', english);

/**
 * One sentence on the chosen technique against naive, band by band: where keeping the spread
 * helps, and where it does not (a footprint that mixes a sharp spike and a wide cloud, which a
 * single lobe cannot fit, as on V-grooves).
 */
export function verdict(errors, technique, levels) {
  const name = techniqueName(technique);
  if (technique === 'naive' || technique === 'renormalized') return t('plot.noSpread', { technique: name });
  const worse = levels.filter((l) => errors[technique].bands[l].rmse > errors.naive.bands[l].rmse);
  if (worse.length === 0) return t('plot.closer', { technique: name });
  return t('plot.worse', { technique: name, levels: worse.join(', ') });
}

/** createErrorDistancePlot(host) → { show(errors), dispose() }; errors as the error table's, or null. */
export function createErrorDistancePlot(host) {
  const box = el('div', 'nm-plot');
  const title = el('p', 'nm-plot-title', t('plot.title'));
  const plotHost = el('div', 'nm-plot-host');
  const note = el('p', 'nm-plot-note', t('plot.pending'));
  let pending = true; // the note says that it waits for the ground truth
  note.setAttribute('aria-live', 'polite');
  box.append(title, plotHost, note);
  host.append(box);
  const plot = createLinePlot(plotHost, {
    xLabel: t('plot.x'), yLabel: t('plot.y'), height: 280, digits: 4, xUnit: '', xStep: 1,
    // from 0, so that a gap between techniques reads at its true size
    xRange: (_u, min, max) => [min - 0.25, max + 0.25],
    yRange: (_u, _min, max) => [0, Math.max(1e-3, max * 1.15)],
    series: TECHNIQUES.map((id) => ({
      label: techniqueName(id), width: id === 'naive' || id === 'renormalized' ? 3 : 2.5, ...TECHNIQUE_STYLES[id],
    })),
  });
  let shown; // the errors object and technique drawn last
  let shownTechnique;
  return {
    /** errors as the error table's (null while the truth converges); technique: the one chosen. */
    show(errors, technique) {
      if (errors === shown && technique === shownTechnique) return;
      shown = errors;
      shownTechnique = technique;
      if (!errors) {
        plot.setData([[], ...TECHNIQUES.map(() => [])]);
        note.textContent = t('plot.pending');
        pending = true;
        return;
      }
      // Bands no pixel fell into stay out of the plot (null), as they stay out of the table.
      const used = errors[TECHNIQUES[0]].bands.filter((b) => TECHNIQUES.some((id) => errors[id].bands[b.level].count > 0));
      plot.setData([used.map((b) => b.level), ...TECHNIQUES.map((id) => used.map((b) => errors[id].bands[b.level].rmse))]);
      note.textContent = verdict(errors, technique, used.map((b) => b.level));
      pending = false;
    },
    /** The sentence under the plot ('' while there are no errors). */
    get note() { return pending ? '' : note.textContent; },
    /** [levels, ...one RMSE series per technique in TECHNIQUES order], as plotted. */
    get data() { return plot.data; },
    toPng: () => plot.toPng(),
    dispose() {
      plot.dispose();
    },
  };
}
