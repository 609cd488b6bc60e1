// The DOM of the asphalt panel: the stage (canvas and a badge saying which model is on), the hover
// readout, the key numbers and the formula. Styled by styles.css under .asphalt-panel.
import english from 'virtual:messages/en/asphalt';
import { messages } from '../../i18n/messages.js';
import { texElement } from '../../ui/tex.js';
import { texText } from '../../ui/texText.js';
import './styles.css';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { makeScrollBox } from '../../ui/scrollBox.js';

const t = messages('asphalt', english);

export function buildAsphaltDom(host) {
  const root = el('div', 'asphalt-panel');
  const stage = el('div', 'asphalt-stage');
  const canvas = el('canvas', 'asphalt-canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('canvasLabel'));
  const badge = el('div', 'asphalt-badge');
  stage.append(canvas, badge);

  const readout = el('p', 'asphalt-readout');
  readout.setAttribute('aria-live', 'polite');
  const summary = definitionList('asphalt-summary');
  const formula = texElement(
    `L_\\text{${texText(t('formula.specular'))}} = \\frac{D(\\mathbf h)\\,G_2(\\mathbf l,\\mathbf v)\\,F(\\theta_d)}{4\\,\\cos\\theta_v}\\,`
    + `E_\\text{${texText(t('formula.sun'))}},`
    + '\\qquad \\cos\\theta_d = \\mathbf l\\cdot\\mathbf h',
    { className: 'asphalt-formula' },
  );
  root.append(stage, readout, summary.element, makeScrollBox(formula, t('formulaBox')));
  host.append(root);

  return {
    stage,
    canvas,
    setBadge(text, on) {
      badge.textContent = text;
      badge.classList.toggle('is-off', !on);
    },
    setReadout(text) {
      readout.textContent = text;
    },
    /** pairs: [term, value, strong]; a strong row is one of the key numbers. */
    setSummary(pairs) {
      summary.set(pairs.map(([term, value, strong]) => [term, value, strong ? 'is-key' : '']));
    },
  };
}
