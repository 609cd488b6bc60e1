// The DOM of the refraction-waves panel: the stage (canvas, a label per medium with its
// wavelength and speed, the total-internal-reflection banner), a play/pause button, the numbers
// and Snell's law with live values. Styles: refraction-waves.css (all under .rw-panel).
import { renderTex, texNumber } from '../ui/tex.js';
import { el } from '../ui/el.js';

const angle = (deg) => `${deg.toFixed(2)}°`;
// A field amplitude: real numbers as they are, complex ones (total internal reflection) as
// magnitude ∠ phase.
const minus = (text) => text.replace('-', '−');
const amplitude = (z) => (Math.abs(z.im) < 1e-12
  ? minus(z.re.toFixed(4))
  : `${Math.hypot(z.re, z.im).toFixed(4)} ∠ ${minus((Math.atan2(z.im, z.re) * 180 / Math.PI).toFixed(1))}°`);
const kmS = (v) => `${Math.round(v).toLocaleString('en-US')} km/s`;

export function buildRefractionWavesDom(host, { onPlayToggle }) {
  const root = el('div', 'rw-panel');
  const stage = el('div', 'rw-stage');
  const canvas = el('canvas', 'rw-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label',
    'Wavefronts of light crossing a horizontal interface: medium 1 above, medium 2 below, with the incident, transmitted and reflected rays.');
  const top = el('div', 'rw-medium rw-medium-1');
  const bottom = el('div', 'rw-medium rw-medium-2');
  const tir = el('div', 'rw-tir');
  tir.setAttribute('role', 'status');
  tir.hidden = true;
  const tirTitle = el('strong', '', 'Total internal reflection');
  const tirDetail = el('span');
  tir.append(tirTitle, tirDetail);
  const message = el('div', 'rw-message');
  message.hidden = true;
  stage.append(canvas, top, bottom, tir, message);

  const controls = el('div', 'rw-controls');
  const play = el('button', 'rw-play');
  play.type = 'button';
  play.addEventListener('click', onPlayToggle);
  controls.append(play);
  const summary = el('dl', 'rw-summary');
  const snell = el('div', 'rw-snell');
  const note = el('p', 'rw-note');
  root.append(stage, controls, summary, snell, note);
  host.append(root);

  const sub = ['', '₁', '₂'];
  const mediumText = (i, m) => `n${sub[i]} = ${m.n.toFixed(3)}   λ${sub[i]} = λ₀/n${sub[i]} = ${m.wavelength.toFixed(1)} nm   `
    + `v${sub[i]} = c/n${sub[i]} = ${m.speed.toFixed(3)} c`;

  return {
    canvas,
    setPlaying(playing) {
      play.textContent = playing ? '❚❚ Pause' : '▶ Play';
      play.setAttribute('aria-pressed', String(playing));
      play.setAttribute('aria-label', playing ? 'Pause the waves' : 'Play the waves');
    },
    /**
     * s: { theta1, theta2 (null: TIR), critical (null: none) in degrees, R, T (unpolarized), m1, m2
     * (mediumWave results with n), depthNm, n1, n2, r, t (complex s-polarized field amplitudes) }.
     */
    show(s) {
      top.textContent = mediumText(1, s.m1);
      bottom.textContent = mediumText(2, s.m2);
      tir.hidden = s.theta2 !== null;
      tirDetail.textContent = s.theta2 === null
        ? `No transmitted wave; the evanescent field below fades within ${s.depthNm.toFixed(0)} nm (1/e).`
        : '';
      stage.classList.toggle('rw-is-tir', s.theta2 === null);
      summary.replaceChildren(...[
        ['Incidence θ₁', angle(s.theta1)],
        ['Transmitted θ₂', s.theta2 === null ? 'none (total internal reflection)' : angle(s.theta2)],
        ['Critical angle', s.critical === null ? 'none (n₁ ≤ n₂)' : angle(s.critical)],
        ['Speeds', `v₁ = ${kmS(s.m1.speedKmS)}, v₂ = ${kmS(s.m2.speedKmS)}`],
        ['Reflected R', s.R.toFixed(4)],
        ['Transmitted T', s.T.toFixed(4)],
      ].map(([term, value]) => {
        const wrap = el('div');
        wrap.append(el('dt', '', term), el('dd', '', value));
        return wrap;
      }));
      note.textContent = 'The picture shows s-polarized light (electric field out of the screen), incident amplitude 1: '
        + `reflected r_s = ${amplitude(s.r)}, transmitted t_s = 1 + r_s = ${amplitude(s.t)}`
        + `${s.theta2 === null ? ' (evanescent)' : ''}. R and T above are for unpolarized light.`;
      const lhs = `n_1 \\sin\\theta_1 = ${texNumber(s.n1, 3)} \\sin ${texNumber(s.theta1, 2)}^\\circ = ${texNumber(s.n1 * Math.sin(s.theta1 * Math.PI / 180), 4)}`;
      renderTex(snell, s.theta2 === null
        ? `${lhs} > n_2 = ${texNumber(s.n2, 3)} \\;\\Rightarrow\\; \\text{no } \\theta_2`
        : `${lhs} = n_2 \\sin\\theta_2 = ${texNumber(s.n2, 3)} \\sin ${texNumber(s.theta2, 2)}^\\circ`);
    },
    showStageMessage(text) {
      message.textContent = text;
      message.hidden = false;
      canvas.hidden = true;
      stage.classList.add('rw-no-gl');
    },
  };
}
