// @ts-check
// Panel `angle-ratio`: one ray meets a flat interface and splits into a reflected part R and a
// refracted part T = 1 − R; stroke widths carry the powers. Past the critical angle (n_i > n_t)
// nothing goes through. Numbers from src/panels/angle-ratio/physics.js (which uses fresnel.js).
import english from 'virtual:messages/en/angle-ratio';
import { messages } from '../../i18n/messages.js';
import { interfaceSplit, interfaceSplitCurve } from './physics.js';
import { el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { angle, fixed, markupNumber, tickLabel } from '../../ui/format.js';
import { cssVar } from '../../ui/theme.js';
import { addSwap } from '../shared/indexPair.js';
import { buildAngleRatioDiagram, svgToPng } from './buildAngleRatioDiagram.js';
import { stoneAnalogy } from './words.js';
import './styles.css';
import { schema } from './schema.js';

export { schema };

const t = messages('angle-ratio', english);

/** A control's value as a sentence writes it: the decimals of its step, in the page's language. */
const shown = (/** @type {string} */ key, /** @type {number} */ value) => tickLabel(value, /** @type {any} */ (schema)[key].step);

/** A labelled horizontal bar with its number; the bar itself is decoration (the number is text). */
function bar(label, className) {
  const row = el('div', `ar-bar-row ${className}`);
  const name = el('span', 'ar-bar-name', label);
  const track = el('span', 'ar-bar-track');
  const fill = el('span', 'ar-bar-fill');
  track.setAttribute('aria-hidden', 'true');
  track.append(fill);
  const value = el('span', 'ar-bar-value');
  row.append(name, track, value);
  return {
    row,
    set(v) {
      fill.style.width = `${markupNumber(100 * v, 2)}%`;
      value.textContent = fixed(v, 4);
    },
  };
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'angle-ratio-panel');
  const figure = el('div', 'ar-figure');
  const diagram = buildAngleRatioDiagram(figure, {
    onAngle(deg) {
      ctx.set({ theta: Math.round(deg * 10) / 10 });
    },
  });
  const bars = el('div', 'ar-bars');
  const rBar = bar(t('barReflected'), 'ar-bar-r');
  const tBar = bar(t('barTransmitted'), 'ar-bar-t');
  bars.append(rBar.row, tBar.row);
  const status = el('p', 'ar-status');
  status.setAttribute('aria-live', 'polite');
  const analogy = el('p', 'ar-analogy');
  panel.append(figure, bars, status, analogy);
  root.append(panel);

  const folder = ctx.gui.addFolder(t('folder'));
  ctx.bind(folder, ['theta', 'nI', 'nT']);
  addSwap(ctx, folder, t('swap'));

  let split = null;
  let pngUrl = null;
  let pngTimer = 0;
  let disposed = false;

  // The PNG export needs an image decode (asynchronous), so a fresh copy is prepared shortly after
  // each change and handed out by png().
  function refreshPng() {
    clearTimeout(pngTimer);
    pngTimer = setTimeout(() => {
      svgToPng(diagram.svg, cssVar('--panel', '#161b22'))
        .then((url) => { if (!disposed) pngUrl = url; })
        .catch(() => { pngUrl = null; });
    }, 250);
  }

  function update() {
    const { theta, nI, nT } = values;
    split = interfaceSplit(theta, nI, nT);
    diagram.set(split, nI, nT);
    rBar.set(split.R);
    tBar.set(split.T);
    setSubscripted(status, split.tir
      ? t('statusTir', { theta: angle(theta, 1), critical: angle(split.critical) })
      : t('status', {
        theta: angle(theta, 1), thetaT: angle(split.thetaT), critical: split.critical === null ? 'none' : angle(split.critical),
      }));
    panel.classList.toggle('ar-is-tir', split.tir);
    analogy.textContent = stoneAnalogy(nI, nT);
    refreshPng();
  }
  update();

  return {
    diagram,
    get split() { return split; },
    update,
    describe() {
      const { theta, nI, nT } = values;
      return t('describe', {
        nI: shown('nI', nI),
        nT: shown('nT', nT),
        theta: angle(theta, 1),
        R: fixed(split.R, 4),
        T: fixed(split.T, 4),
        tir: split.tir ? 'yes' : 'no',
        critical: split.tir ? angle(split.critical) : '',
        thetaT: split.tir ? '' : angle(split.thetaT),
      });
    },
    csv() {
      const { theta, R, T } = interfaceSplitCurve(values.nI, values.nT);
      return { filename: `angle-ratio-nI${values.nI}-nT${values.nT}.csv`, columns: { theta_deg: theta, R, T } };
    },
    png: () => pngUrl,
    dispose() {
      disposed = true;
      clearTimeout(pngTimer);
      diagram.dispose();
      panel.remove();
    },
  };
}
