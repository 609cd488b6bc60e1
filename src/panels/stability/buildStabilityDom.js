// The DOM of the stability panel: a note on what mediump really is here, the class legend, the
// two maps (GPU and JavaScript) each with its counts, and the probe readout.
import { el } from '../../ui/el.js';
import { CLASS_NAMES } from '../../methods/stabilityMap.js';
import { CLASS_LABELS } from '../shared/classLabels.js';
import { createMapFigure, swatch } from '../shared/createMapFigure.js';
import english from 'virtual:messages/en/stability';
import { messages } from '../../i18n/messages.js';

const t = messages('stability', english);

export function buildStabilityDom(host) {
  const root = el('div', 'st-panel');
  const note = el('p', 'st-note');
  const legend = el('ul', 'st-legend');
  legend.setAttribute('aria-label', t('legend'));
  for (const cls of CLASS_NAMES) {
    const item = el('li');
    item.append(swatch(cls), CLASS_LABELS[cls]);
    legend.append(item);
  }
  const critical = el('li');
  critical.append(el('span', 'st-line st-line-critical'), t('criticalLine'));
  legend.append(critical);
  const maps = el('div', 'st-maps');
  const gpu = createMapFigure('gpu');
  const js = createMapFigure('js');
  maps.append(gpu.figure, js.figure);
  const readout = el('p', 'st-readout');
  readout.setAttribute('aria-live', 'polite');
  root.append(note, legend, maps, readout);
  host.append(root);
  return {
    root,
    maps,
    gpu,
    js,
    setNote(text) { note.textContent = text; note.hidden = !text; },
    setReadout(text) { readout.textContent = text || t('hint'); },
  };
}
