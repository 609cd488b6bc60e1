// The DOM of the metals panel below its spheres: F0 swatches (buttons that pick the metal), the
// per-channel table and the plot's caption. F0 is a linear reflectance; swatches show it encoded
// to sRGB (the sRGB transfer function, src/ui/srgb.js) with the linear numbers beside.
import { linearToHex } from '../../ui/srgb.js';
import { el } from '../../ui/el.js';
import { scrollBox } from '../../ui/scrollBox.js';
import { lectureNote } from '../../ui/lectureNote.js';
import { fixed } from '../../ui/format.js';
import { metalTableRow } from './metalTableRow.js';
import { indexText } from '../shared/indexText.js';
import { materialName } from '../shared/materialName.js';
import english from 'virtual:messages/en/metals';
import { messages } from '../../i18n/messages.js';

const t = messages('metals', english);

/** CSS colour of a linear RGB reflectance. */
export function swatchColor(rgb) {
  return linearToHex(rgb);
}

const CHANNEL_VARS = { red: '--c-red', green: '--c-green', blue: '--c-blue' };

/**
 * host: the panel element. metals: [{ id, name, f0 }]. onPick(id) runs when a metal's swatch is
 * chosen (click, Enter or Space: they are buttons).
 */
export function buildMetalsDom(host, metals, onPick) {
  const swatchRow = el('div', 'mt-swatches');
  swatchRow.setAttribute('role', 'group');
  swatchRow.setAttribute('aria-label', t('swatches'));
  // Three numbers that wrap as a group when a swatch is narrow (text stays "0.956 0.792 0.408").
  const fillNumbers = (node, rgb) => {
    const parts = rgb.map((v) => el('span', '', fixed(v, 3)));
    node.replaceChildren(...parts.flatMap((part, i) => (i ? [' ', part] : [part])));
  };

  const dielectric = el('div', 'mt-swatch mt-dielectric');
  dielectric.dataset.material = 'dielectric';
  const dielectricChip = el('span', 'mt-chip');
  const dielectricIndex = el('span', 'mt-index');
  const dielectricF0 = el('span', 'mt-f0');
  dielectric.append(dielectricChip, el('span', 'mt-name', t('dielectric')), dielectricIndex, dielectricF0);
  swatchRow.append(dielectric);

  const buttons = metals.map((metal) => {
    const button = el('button', 'mt-swatch');
    button.type = 'button';
    button.dataset.metal = metal.id;
    const chip = el('span', 'mt-chip');
    chip.style.background = swatchColor(metal.f0);
    const f0 = el('span', 'mt-f0');
    fillNumbers(f0, metal.f0);
    // Its name is what it shows (the group says these are F0 in red, green, blue), so a voice
    // command of the visible words reaches it.
    button.append(chip, el('span', 'mt-name', metal.name), ' ', f0);
    button.addEventListener('click', () => onPick(metal.id));
    swatchRow.append(button);
    return button;
  });

  const table = el('table', 'mt-table');
  const head = el('tr');
  const columns = ['colChannel', 'colIndex', 'colF0', 'colMaxError', 'colLowest', 'colPseudoBrewster', 'colPrincipal'];
  for (const word of columns) {
    const th = el('th', '', t(word));
    th.scope = 'col';
    head.append(th);
  }
  const body = el('tbody');
  table.append(el('caption', 'mt-caption'), el('thead'), body);
  table.tHead.append(head);

  const plotHost = el('div', 'mt-plot');
  plotHost.setAttribute('aria-label', t('plot'));
  // F0 here is the reflectance at three wavelengths, not a colour integrated over the spectrum.
  const sampled = el('p', 'mt-sampled', t('sampled'));
  host.append(swatchRow, sampled);
  const note = lectureNote(host);
  host.append(scrollBox(table, t('table')), plotHost);

  return {
    plotHost,
    /**
     * The swatches as a control of the panel's own (ctx.tie): a deck's lock of the metal disables
     * them (shown at full contrast with a dashed frame, as a locked control is); they always show.
     */
    swatchControl: {
      enable(on) {
        for (const b of buttons) b.disabled = !on;
        swatchRow.classList.toggle('is-locked', !on);
      },
      show() {},
    },
    /** The note on the lecture's "almost no Fresnel factor" (words.js) and its source. */
    setNote(text, source) {
      note.set(text, source);
    },
    /** Dielectric swatch (grey F0), and which metal is chosen. */
    setSwatches({ n, f0 }, metalId) {
      dielectricChip.style.background = swatchColor([f0, f0, f0]);
      dielectricIndex.textContent = t('index', { n: indexText(n) });
      fillNumbers(dielectricF0, [f0, f0, f0]);
      for (const b of buttons) b.setAttribute('aria-pressed', String(b.dataset.metal === metalId));
    },
    /** metal: { id, n, k, rgbNm }; stats from metalCurveStats. */
    setTable(metal, stats) {
      table.caption.textContent = t('caption', { metal: materialName(metal.id) });
      body.replaceChildren(...stats.map((s, ch) => {
        const row = el('tr');
        const [channel, ...cells] = metalTableRow(metal, s, ch);
        const name = el('th', '', channel);
        name.scope = 'row';
        name.style.color = `var(${CHANNEL_VARS[s.channel]})`;
        row.append(name, ...cells.map((text) => el('td', '', text)));
        return row;
      }));
    },
  };
}
