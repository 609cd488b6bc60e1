// The DOM of the refraction-waves panel: the stage (canvas, a label per medium with its
// wavelength and speed, the total-internal-reflection banner), a play/pause button, the numbers
// and Snell's law with live values. Styles: styles.css (all under .rw-panel).
import { DEG, toDegrees } from '../../optics/angles.js';
import { angle, fixed, grouped } from '../../ui/format.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { renderTex, texNumber } from '../../ui/tex.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { makeScrollBox } from '../../ui/scrollBox.js';

// A field amplitude: real numbers as they are, complex ones (total internal reflection) as
// magnitude ∠ phase.
const amplitude = (z) => (Math.abs(z.im) < 1e-12
  ? fixed(z.re, 4)
  : `${fixed(Math.hypot(z.re, z.im), 4)} ∠ ${angle(toDegrees(Math.atan2(z.im, z.re)), 1)}`);
const kmS = (v) => `${grouped(v)} km/s`;

export function buildRefractionWavesDom(host, { onPlayToggle }) {
  const root = el('div', 'rw-panel');
  const stage = el('div', 'rw-stage');
  const canvas = el('canvas', 'rw-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label',
    'Wavefronts of light crossing a horizontal interface: the incident medium above, the transmitted medium below, '
    + 'with the incident, transmitted and reflected rays.');
  const top = el('div', 'rw-medium rw-medium-1');
  const bottom = el('div', 'rw-medium rw-medium-2');
  const tir = el('div', 'rw-tir');
  tir.setAttribute('role', 'status');
  tir.hidden = true;
  const tirTitle = el('strong', '', 'Total internal reflection');
  const tirDetail = el('span');
  tir.append(tirTitle, tirDetail);
  stage.append(canvas, top, bottom, tir);

  const controls = el('div', 'rw-controls');
  const play = el('button', 'rw-play');
  play.type = 'button';
  play.addEventListener('click', onPlayToggle);
  controls.append(play);
  const summary = definitionList('rw-summary', { write: setSubscripted });
  const snell = makeScrollBox(el('div', 'rw-snell'), 'Snell’s law at these indices');
  const note = el('p', 'rw-note');
  root.append(stage, controls, summary.element, snell, note);
  host.append(root);

  const mediumText = (side, m) => `n_${side} = ${fixed(m.n, 3)}   λ_${side} = λ_0/n_${side} = ${fixed(m.wavelength, 1)} nm   `
    + `v_${side} = c/n_${side} = ${fixed(m.speed, 3)} c`;

  return {
    stage,
    canvas,
    setPlaying(playing) {
      play.textContent = playing ? '❚❚ Pause' : '▶ Play';
      play.setAttribute('aria-pressed', String(playing));
      play.setAttribute('aria-label', playing ? 'Pause the waves' : 'Play the waves');
    },
    /**
     * s: { thetaI, thetaT (null: TIR), critical (null: none) in degrees, R, T (unpolarized), mI, mT
     * (mediumWave results with n), depthNm, nI, nT, r, t (complex s-polarized field amplitudes) }.
     */
    show(s) {
      setSubscripted(top, mediumText('i', s.mI));
      setSubscripted(bottom, mediumText('t', s.mT));
      tir.hidden = s.thetaT !== null;
      tirDetail.textContent = s.thetaT === null
        ? `No propagating transmitted wave; the evanescent field's amplitude below falls to 1/e within ${fixed(s.depthNm, 0)} nm.`
        : '';
      stage.classList.toggle('rw-is-tir', s.thetaT === null);
      summary.set([
        ['Incidence θ_i', angle(s.thetaI)],
        ['Transmitted θ_t', s.thetaT === null ? 'none (total internal reflection)' : angle(s.thetaT)],
        ['Critical angle', s.critical === null ? 'none (n_i ≤ n_t)' : angle(s.critical)],
        ['Phase speeds c/n', `v_i = ${kmS(s.mI.speedKmS)}, v_t = ${kmS(s.mT.speedKmS)}`],
        ['Reflected R', fixed(s.R, 4)],
        ['Transmitted T', fixed(s.T, 4)],
      ]);
      note.textContent = 'The picture shows s-polarized light (electric field out of the screen), incident amplitude 1: '
        + `reflected r_s = ${amplitude(s.r)}, transmitted t_s = 1 + r_s = ${amplitude(s.t)}`
        + `${s.thetaT === null ? ' (evanescent)' : ''}. R and T above are for unpolarized light.`;
      const lhs = `n_i \\sin\\theta_i = ${texNumber(s.nI, 3)} \\sin ${texNumber(s.thetaI, 2)}^\\circ`
        + ` = ${texNumber(s.nI * Math.sin(s.thetaI * DEG), 4)}`;
      renderTex(snell, s.thetaT === null
        ? `${lhs} > n_t = ${texNumber(s.nT, 3)} \\;\\Rightarrow\\; \\text{no } \\theta_t`
        : `${lhs} = n_t \\sin\\theta_t = ${texNumber(s.nT, 3)} \\sin ${texNumber(s.thetaT, 2)}^\\circ`);
    },
  };
}
