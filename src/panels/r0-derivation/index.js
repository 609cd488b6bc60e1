// @ts-check
// Panel `r0-derivation`: the lecture's derivation of R(0°), line by line, each line typeset and
// evaluated as written (src/panels/r0-derivation/physics.js) at the current indices, with a check that all
// lines agree and that the last equals normalIncidence and fresnelExact(1, …). No WebGL: KaTeX.
import { fresnelExact, normalIncidence } from '../../optics/fresnel.js';
import { maxSpread, r0Steps } from './physics.js';
import { el } from '../../ui/el.js';
import { fixed as fixedTo, sci } from '../../ui/format.js';
import { renderTex, texElement, texNumber } from '../../ui/tex.js';
import { definitionList } from '../../ui/definitionList.js';
import { addSwap } from '../shared/indexPair.js';
import './styles.css';
import { schema } from './schema.js';
import { makeScrollBox, scrollBox } from '../../ui/scrollBox.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/r0-derivation';
import { messages } from '../../i18n/messages.js';

export { schema };

const t = messages('r0-derivation', english);
const DIGITS = 6;
const fixed = (value) => fixedTo(value, DIGITS);
/** Differences at the rounding level: 0 or an exponent, never a misleading 0.000000. */
const tiny = (value) => (value === 0 ? t('identical') : sci(value, 1));

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'r0-panel');
  const first = r0Steps(values.nI, values.nT); // the TeX is symbolic: typeset once

  const setupHead = el('p', 'r0-head', t('head'));
  const setup = el('table', 'r0-steps r0-setup');
  const setupCells = first.setup.map((step) => {
    const tr = el('tr');
    const expr = el('td', 'r0-expr');
    expr.append(texElement(step.tex, { display: false, tag: 'span' }));
    const value = el('td', 'r0-value');
    tr.append(expr, el('td', 'r0-note', t(`step.${step.step}`)), value);
    setup.append(tr);
    return value;
  });

  const lines = el('table', 'r0-steps r0-lines');
  const caption = el('caption', 'r0-caption', t('caption'));
  // Column headers for screen readers (every cell has one); the caption and layout say it on screen.
  const head = el('thead', 'sr-only');
  const headRow = el('tr');
  for (const word of ['colLeft', 'colExpression', 'colStep', 'colValue']) {
    const th = el('th', '', t(word));
    th.scope = 'col';
    headRow.append(th);
  }
  head.append(headRow);
  lines.append(caption, head);
  const lineCells = first.lines.map((line, i) => {
    const tr = el('tr');
    const lhs = el('td', 'r0-lhs');
    lhs.append(texElement(i === 0 ? 'R(0^\\circ) =' : '=', { display: false, tag: 'span' }));
    const expr = el('td', 'r0-expr');
    expr.append(texElement(`\\displaystyle ${line.tex}`, { display: false, tag: 'span' }));
    const value = el('td', 'r0-value');
    value.dataset.line = String(i + 1);
    // The step's words head its row: a screen reader says what the line does before its numbers.
    const note = el('th', 'r0-note', t(`step.${line.step}`));
    note.scope = 'row';
    tr.append(lhs, expr, note, value);
    lines.append(tr);
    return value;
  });

  const check = el('div', 'r0-check');
  const verdict = el('p', 'r0-verdict');
  const refs = definitionList('r0-refs', { valueClass: 'r0-value' });
  const spreadOut = refs.add(t('spread'));
  const normalOut = refs.add(t('normal'));
  const exactOut = refs.add(t('exact'));
  const numbers = makeScrollBox(el('div', 'r0-numbers'), t('numbers'));
  check.append(verdict, refs.element, numbers);

  panel.append(setupHead, scrollBox(setup, t('setup')), scrollBox(lines, t('lines')), check);
  root.append(panel);

  ctx.bind(ctx.gui, ['nI', 'nT']);
  addSwap(ctx, ctx.gui, t('swap'));

  let steps = first;
  let spread = 0;

  function update() {
    const { nI, nT } = values;
    steps = r0Steps(nI, nT);
    steps.setup.forEach((step, i) => { setupCells[i].textContent = fixed(step.value); });
    steps.lines.forEach((line, i) => { lineCells[i].textContent = fixed(line.value); });
    const all = steps.lines.map((l) => l.value);
    spread = maxSpread(all);
    const normal = normalIncidence(nI, nT);
    const exact = fresnelExact(1, nI, nT);
    const agree = spread < 1e-12 && Math.abs(all.at(-1) - normal) < 1e-12 && Math.abs(all.at(-1) - exact) < 1e-12;
    verdict.textContent = agree
      ? t('agree', { count: String(all.length), r0: fixed(all.at(-1)), nI: fixedTo(nI, 4), nT: fixedTo(nT, 4) })
      : t('disagree', { spread: tiny(spread) });
    panel.classList.toggle('r0-bad', !agree);
    spreadOut.textContent = t('spreadValue', { spread: tiny(spread) });
    normalOut.textContent = fixed(normal);
    exactOut.textContent = fixed(exact);
    const [tex, i] = [texNumber(nT), texNumber(nI)];
    renderTex(numbers, String.raw`R(0^\circ) = \left(\frac{${tex} - ${i}}{${tex} + ${i}}\right)^{2}
      = \left(\frac{${fixed(nT - nI)}}{${fixed(nT + nI)}}\right)^{2} = ${fixed(all.at(-1))}`);
  }
  update();

  return {
    update,
    get steps() { return steps; },
    describe() {
      const { nI, nT } = values;
      return t('describe', {
        nI: indexText(nI), nT: indexText(nT), c: fixed(steps.setup[0].value), count: String(steps.lines.length),
        r0: fixed(steps.lines.at(-1).value), spread: tiny(spread),
      });
    },
    csv() {
      const rows = [...steps.setup, ...steps.lines];
      return {
        filename: `r0-derivation-nI${values.nI}-nT${values.nT}.csv`,
        columns: {
          line: rows.map((_, i) => i + 1),
          is_R: rows.map((_, i) => (i < steps.setup.length ? 0 : 1)),
          value: rows.map((r) => r.value),
        },
      };
    },
    dispose() {
      panel.remove();
    },
  };
}
