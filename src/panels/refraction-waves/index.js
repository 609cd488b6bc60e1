// @ts-check
// Panel `refraction-waves`: plane wavefronts crossing a horizontal interface, slowing to c/n and
// shortening to λ/n, bent by Snell's law; past the critical angle only an evanescent field is
// left below. The wave numbers and amplitudes come from src/optics/waves.js; the fragment shader
// (refraction-waves.frag.glsl) only evaluates them. It animates only while playing.
import english from 'virtual:messages/en/refraction-waves';
import { messages } from '../../i18n/messages.js';
import { createShaderView } from '../../gl/createShaderView.js';
import { DEG } from '../../optics/angles.js';
import { criticalAngle, fresnelExact } from '../../optics/fresnel.js';
import { evanescentDepth, mediumWave, waveField } from '../../optics/waves.js';
import { startWebGL } from '../shared/startWebGL.js';
import { angle, fixed, tickLabel } from '../../ui/format.js';
import { buildRefractionWavesDom } from './buildRefractionWavesDom.js';
import fragment from './refraction-waves.frag.glsl?raw';
import './styles.css';
import { schema } from './schema.js';

export { schema };

const t = messages('refraction-waves', english);

/** A control's value as a sentence writes it: the decimals of its step, in the page's language. */
const shown = (/** @type {string} */ key, /** @type {number} */ value) => tickLabel(value, /** @type {any} */ (schema)[key].step);

const LAMBDA0_NM = 550; // the vacuum wavelength quoted in the labels (green light)
const HALF_HEIGHT = 3;  // the view is 6 vacuum wavelengths tall
const RAY_LENGTH = 2.4;

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  // Reduced motion: start on a still frame; Play is one click (or Enter) away.
  if (ctx.reducedMotion) ctx.set({ play: false });
  const dom = buildRefractionWavesDom(root, { onPlayToggle: () => ctx.set({ play: !values.play }) });
  const view = startWebGL(dom.stage, () => createShaderView(dom.canvas, {
    fragment,
    onFrame: ctx.frameDrawn,
    uniforms: {
      uHalfHeight: { value: HALF_HEIGHT },
      uKx: { value: 0 },
      uK1y: { value: 0 },
      uK2y: { value: 0 },
      uKappa: { value: 0 },
      uR: { value: [0, 0] },
      uT: { value: [1, 0] },
      uPhase: { value: 0 },
      uShowReflected: { value: false },
      uDirI: { value: [0, -1] },
      uDirR: { value: [0, 1] },
      uDirT: { value: [0, -1] },
      uRayLength: { value: RAY_LENGTH },
    },
  }), t('noWebgl'));

  ctx.bind(ctx.gui.addFolder(t('folder.interface')), ['angle', 'nI', 'nT', 'reflected']);
  ctx.bind(ctx.gui.addFolder(t('folder.animation')), ['play', 'speed']);

  // Animation: a requestAnimationFrame loop that runs only while playing and on screen.
  let raf = 0;
  let last = 0;
  let onScreen = true;
  const tick = (now) => {
    raf = 0;
    if (last) view.uniforms.uPhase.value = (view.uniforms.uPhase.value + 2 * Math.PI * values.speed * (now - last) / 1000) % (2 * Math.PI);
    last = now;
    view.render();
    raf = requestAnimationFrame(tick);
  };
  function syncLoop() {
    const run = Boolean(view) && values.play && onScreen;
    if (run && !raf) {
      last = 0;
      raf = requestAnimationFrame(tick);
    } else if (!run && raf) {
      cancelAnimationFrame(raf);
      raf = 0;
    }
  }
  const visibility = new IntersectionObserver((entries) => {
    onScreen = entries.some((entry) => entry.isIntersecting);
    syncLoop();
  });
  visibility.observe(dom.canvas);

  let state = null;
  function update() {
    const thetaI = values.angle * DEG;
    const { nI, nT } = values;
    const w = waveField(thetaI, nI, nT);
    const critical = criticalAngle(nI, nT);
    const R = fresnelExact(Math.cos(thetaI), nI, nT);
    state = {
      nI, nT, R, T: 1 - R,
      thetaI: values.angle,
      thetaT: w.tir ? null : w.theta2 / DEG,
      critical: critical === null ? null : critical / DEG,
      depthNm: w.tir ? evanescentDepth(thetaI, nI, nT, LAMBDA0_NM) : null,
      mI: { n: nI, ...mediumWave(nI, LAMBDA0_NM) },
      mT: { n: nT, ...mediumWave(nT, LAMBDA0_NM) },
      r: w.r,
      t: w.t,
    };
    dom.show(state);
    dom.setPlaying(values.play);
    if (view) {
      const u = view.uniforms;
      u.uKx.value = w.kx;
      u.uK1y.value = w.k1y;
      u.uK2y.value = w.k2y;
      u.uKappa.value = w.kappa;
      u.uR.value = [w.r.re, w.r.im];
      u.uT.value = [w.t.re, w.t.im];
      u.uShowReflected.value = values.reflected;
      const s = Math.sin(thetaI);
      const c = Math.cos(thetaI);
      u.uDirI.value = [s, -c];
      u.uDirR.value = [s, c];
      u.uDirT.value = w.tir ? [0, -1] : [Math.sin(w.theta2), -Math.cos(w.theta2)];
      view.render();
    }
    syncLoop();
  }
  update();

  return {
    view,
    get playing() { return raf !== 0; },
    update,
    describe() {
      const { mI, mT } = state;
      const media = t('describeMedia', {
        nI: shown('nI', state.nI), wavelengthI: fixed(mI.wavelength, 1), speedI: fixed(mI.speed, 3),
        nT: shown('nT', state.nT), wavelengthT: fixed(mT.wavelength, 1), speedT: fixed(mT.speed, 3),
      });
      return `${media} ${state.thetaT === null
        ? t('describeTir', { theta: angle(state.thetaI), critical: angle(state.critical), depth: fixed(state.depthNm, 0) })
        : t('describeRefracted', {
          theta: angle(state.thetaI),
          thetaT: angle(state.thetaT),
          critical: state.critical === null ? 'none' : angle(state.critical),
          R: fixed(state.R, 4),
          T: fixed(state.T, 4),
        })}`;
    },
    png: view ? () => view.toDataURL() : null,
    dispose() {
      if (raf) cancelAnimationFrame(raf);
      raf = 0;
      visibility.disconnect();
      view?.dispose();
    },
  };
}
