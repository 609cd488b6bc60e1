// The DOM of the refraction-waves panel: the stage (canvas, a label per medium with its
// wavelength and speed, the total-internal-reflection banner), a play/pause button, the numbers
// and Snell's law with live values. Styles: styles.css (all under .rw-panel).
import english from 'virtual:messages/en/refraction-waves';
import { messages } from '../../i18n/messages.js';
import { DEG, toDegrees } from '../../optics/angles.js';
import { angle, fixed, grouped } from '../../ui/format.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { renderTex, texNumber } from '../../ui/tex.js';
import { texText } from '../../ui/texText.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { makeScrollBox } from '../../ui/scrollBox.js';

const t = messages('refraction-waves', english);

// A field amplitude: real numbers as they are, complex ones (total internal reflection) as
// magnitude ∠ phase.
const amplitude = (z) => (Math.abs(z.im) < 1e-12
  ? fixed(z.re, 4)
  : `${fixed(Math.hypot(z.re, z.im), 4)} ∠ ${angle(toDegrees(Math.atan2(z.im, z.re)), 1)}`);
const kmS = (v) => t('speedKmS', { speed: grouped(v) });

export function buildRefractionWavesDom(host, { onPlayToggle }) {
  const root = el('div', 'rw-panel');
  const stage = el('div', 'rw-stage');
  const canvas = el('canvas', 'rw-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('canvasLabel'));
  const top = el('div', 'rw-medium rw-medium-1');
  const bottom = el('div', 'rw-medium rw-medium-2');
  const tir = el('div', 'rw-tir');
  tir.setAttribute('role', 'status');
  tir.hidden = true;
  const tirTitle = el('strong', '', t('tirTitle'));
  const tirDetail = el('span');
  tir.append(tirTitle, tirDetail);
  stage.append(canvas, top, bottom, tir);

  const controls = el('div', 'rw-controls');
  const play = el('button', 'rw-play');
  play.type = 'button';
  play.addEventListener('click', onPlayToggle);
  controls.append(play);
  const summary = definitionList('rw-summary', { write: setSubscripted });
  const snell = makeScrollBox(el('div', 'rw-snell'), t('snellBox'));
  const note = el('p', 'rw-note');
  root.append(stage, controls, summary.element, snell, note);
  host.append(root);

  const mediumText = (side, m) => t('medium', { side, n: fixed(m.n, 3), wavelength: fixed(m.wavelength, 1), speed: fixed(m.speed, 3) });

  return {
    stage,
    canvas,
    setPlaying(playing) {
      play.textContent = t(playing ? 'pause' : 'play');
      play.setAttribute('aria-pressed', String(playing));
      play.setAttribute('aria-label', t(playing ? 'pauseLabel' : 'playLabel'));
    },
    /**
     * s: { thetaI, thetaT (null: TIR), critical (null: none) in degrees, R, T (unpolarized), mI, mT
     * (mediumWave results with n), depthNm, nI, nT, r, t (complex s-polarized field amplitudes) }.
     */
    show(s) {
      setSubscripted(top, mediumText('i', s.mI));
      setSubscripted(bottom, mediumText('t', s.mT));
      tir.hidden = s.thetaT !== null;
      tirDetail.textContent = s.thetaT === null ? t('tirDetail', { depth: fixed(s.depthNm, 0) }) : '';
      stage.classList.toggle('rw-is-tir', s.thetaT === null);
      summary.set([
        [t('summary.incidence'), angle(s.thetaI)],
        [t('summary.transmitted'), s.thetaT === null ? t('summary.transmittedNone') : angle(s.thetaT)],
        [t('summary.critical'), s.critical === null ? t('summary.criticalNone') : angle(s.critical)],
        [t('summary.speeds'), t('summary.speedsValue', { vI: kmS(s.mI.speedKmS), vT: kmS(s.mT.speedKmS) })],
        [t('summary.reflected'), fixed(s.R, 4)],
        [t('summary.transmittedT'), fixed(s.T, 4)],
      ]);
      note.textContent = t('note', { r: amplitude(s.r), t: amplitude(s.t), evanescent: s.thetaT === null ? 'yes' : 'no' });
      const lhs = `n_i \\sin\\theta_i = ${texNumber(s.nI, 3)} \\sin ${texNumber(s.thetaI, 2)}^\\circ`
        + ` = ${texNumber(s.nI * Math.sin(s.thetaI * DEG), 4)}`;
      renderTex(snell, s.thetaT === null
        ? `${lhs} > n_t = ${texNumber(s.nT, 3)} \\;\\Rightarrow\\; \\text{${texText(t('formula.noRefracted'))}}`
        : `${lhs} = n_t \\sin\\theta_t = ${texNumber(s.nT, 3)} \\sin ${texNumber(s.thetaT, 2)}^\\circ`);
    },
  };
}
