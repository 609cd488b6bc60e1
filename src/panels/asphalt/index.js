// @ts-check
// Panel `asphalt`: does a rough road have a specular highlight? A ray-cast road under a low sun
// ahead of the camera; overhead it is dull, near grazing it shines (lecture, "Specular"). Two
// factors grow towards grazing: the GGX lobe D·G2/(4 cosθl cosθv) gathers the reflected light
// into a forward beam, and F at the half-vector angle θd rises; the summary gives each one's share.
// The share of sunlight reflected specularly stays small (a few per cent, about the road's diffuse
// albedo): the sheen is concentrated light, not a large share of it. Fresnel off keeps F = R0 and
// shows what a model without it misses. Every number comes from physics.js (float64).
import english from 'virtual:messages/en/asphalt';
import { messages } from '../../i18n/messages.js';
import { createShaderView } from '../../gl/createShaderView.js';
import { DEG } from '../../optics/angles.js';
import { normalIncidence } from '../../optics/fresnel.js';
import { startWebGL } from '../shared/startWebGL.js';
import { readByPointer } from '../../ui/readByPointer.js';
import { fixed, tickLabel } from '../../ui/format.js';
import {
  SCENE, cameraBasis, highlightInView, lambertianEquivalent, pixelRay, shadeRoad, sheenGrowth, specularAlbedo, sunDirection,
} from './physics.js';
import { buildAsphaltDom } from './buildAsphaltDom.js';
import fragment from './asphalt.frag.glsl?raw';
import { schema } from './schema.js';

export { schema };

const t = messages('asphalt', english);
const f3 = (x) => fixed(x, 3);
const deg = (x) => `${fixed(x, 1)}°`;
const percent = (x) => `${fixed(100 * x, 1)} %`;
const times = (x) => `×${fixed(x, 1)}`;

/** Mean RGB (0–255) of a square of drawing-buffer pixels around CSS (x, y), drawn just now. */
function readBlock(view, x, y, radius = 3) {
  view.readPixel(x, y); // draws the frame; the buffer is readable until this task ends
  const { gl } = view;
  const ratio = view.pixelRatio;
  const size = 2 * radius + 1;
  const cx = Math.floor(x * ratio);
  const cy = gl.drawingBufferHeight - 1 - Math.floor(y * ratio);
  const x0 = Math.min(Math.max(0, cx - radius), gl.drawingBufferWidth - size);
  const y0 = Math.min(Math.max(0, cy - radius), gl.drawingBufferHeight - size);
  const out = new Uint8Array(size * size * 4);
  gl.readPixels(x0, y0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, out);
  const sum = [0, 0, 0];
  for (let i = 0; i < out.length; i += 4) for (let c = 0; c < 3; c += 1) sum[c] += out[i + c];
  return sum.map((s) => s / (size * size));
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  /** A control's value as it is written in a sentence: the decimals of its step, in the page's language. */
  const shown = (key) => tickLabel(values[key], schema[key].step);
  const dom = buildAsphaltDom(root);
  const view = startWebGL(dom.stage, () => createShaderView(dom.canvas, {
    fragment,
    cache: { live: ['uN', 'uFresnel'] }, // the index and the Fresnel switch redraw only F (asphalt.frag.glsl)
    onFrame: ctx.frameDrawn,
    uniforms: {
      uForward: { value: [0, -1, 0] }, uUp: { value: [0, 0, 1] }, uRight: { value: [-1, 0, 0] },
      uSunDir: { value: [0, 0.17, 0.98] },
      uTanHalfFov: { value: Math.tan((SCENE.fovY / 2) * DEG) },
      uCameraHeight: { value: SCENE.cameraHeight },
      uN: { value: 1.55 }, uAlpha: { value: 0.64 }, uFresnel: { value: 1 },
      uAlbedo: { value: SCENE.albedo }, uSun: { value: SCENE.sun }, uAmbient: { value: SCENE.ambient },
      uExposure: { value: SCENE.exposure },
    },
  }), t('noWebgl'));

  ctx.bind(ctx.gui.addFolder(t('folder.viewSun')), ['camEl', 'sunEl']);
  ctx.bind(ctx.gui.addFolder(t('folder.road')), ['roughness', 'nT', 'fresnel']);

  const aspect = () => {
    const rect = dom.canvas.getBoundingClientRect();
    return rect.width > 0 && rect.height > 0 ? rect.width / rect.height : 2;
  };
  let state = null;
  // What the camera does not change is computed once per sun, roughness, index and switch.
  let sunKey = '';
  let albedo = 0;
  let growth = null;

  function update() {
    state = highlightInView(values, aspect());
    const { peak, centre } = state;
    const r0 = normalIncidence(1, values.nT);
    const key = [values.sunEl, values.roughness, values.nT, values.fresnel].join();
    if (key !== sunKey) {
      sunKey = key;
      albedo = specularAlbedo(values);
    }
    growth = sheenGrowth(values, aspect());
    dom.setBadge(values.fresnel ? t('badgeOn') : t('badgeOff', { r0: f3(r0) }), values.fresnel);
    dom.setSummary([
      [t('summary.centre'), t('summary.centreValue', { F: f3(centre.F), thetaD: deg(centre.thetaD) }), true],
      [t('summary.peak'), t('summary.peakValue', {
        below: deg(peak.below), specular: f3(peak.specular), thetaD: deg(peak.thetaD), F: f3(peak.F),
      }), true],
      [t('summary.diffuse'), f3(peak.diffuse)],
      [t('summary.ratio'), `${fixed(peak.specular / peak.diffuse, 1)}×`],
      [t('summary.growth'), Number.isFinite(growth.total)
        ? t('summary.growthValue', {
          total: times(growth.total), lobe: times(growth.lobe), fresnel: times(growth.fresnel), overall: times(growth.overall),
        })
        : t('summary.growthNone')],
      [t('summary.albedo', { sunEl: deg(values.sunEl) }),
        t('summary.albedoValue', { albedo: percent(albedo), diffuse: percent(SCENE.albedo) })],
      [t('summary.r0'), f3(r0)],
    ]);
    if (!view) return;
    const basis = cameraBasis(values.camEl);
    const u = view.uniforms;
    u.uForward.value = basis.forward;
    u.uUp.value = basis.up;
    u.uRight.value = basis.right;
    u.uSunDir.value = sunDirection(values.sunEl);
    u.uN.value = values.nT;
    u.uAlpha.value = values.roughness * values.roughness;
    u.uFresnel.value = values.fresnel ? 1 : 0;
    view.render();
  }

  // Hovering or tapping the road: the angle θd between the sun and the half-vector there, and F(θd).
  const onHover = (event) => {
    const rect = dom.canvas.getBoundingClientRect();
    const ndcX = (2 * (event.clientX - rect.left)) / rect.width - 1;
    const ndcY = 1 - (2 * (event.clientY - rect.top)) / rect.height;
    const hit = shadeRoad(pixelRay(values.camEl, ndcX, ndcY, rect.width / rect.height), values);
    dom.setReadout(hit
      ? t('readoutRoad', {
        distance: fixed(hit.distance, 1), below: deg(hit.below), thetaD: deg(hit.thetaD), F: f3(hit.F), specular: f3(hit.specular),
        diffuse: f3(hit.diffuse),
      })
      : t('readoutSky'));
  };
  const onLeave = () => dom.setReadout(t('hint'));
  // Keyboard: arrows raise or lower the camera (Shift for 5°), Home overhead, End grazing.
  const onKey = (event) => {
    const step = event.shiftKey ? 5 : 1;
    const { min, max } = schema.camEl;
    const next = { ArrowUp: values.camEl + step, ArrowRight: values.camEl + step, ArrowDown: values.camEl - step,
      ArrowLeft: values.camEl - step, Home: max, End: min }[event.key];
    if (next === undefined) return;
    event.preventDefault();
    ctx.set({ camEl: Math.min(max, Math.max(min, next)) });
  };
  const stopReading = readByPointer(dom.canvas, onHover, onLeave);
  dom.canvas.addEventListener('keydown', onKey);
  const resize = new ResizeObserver(() => update());
  resize.observe(dom.canvas);
  onLeave();
  update();

  return {
    view,
    get state() { return state; },
    /** Mean RGB around the brightest highlight in view (where the float64 model puts it). */
    probePeak() {
      const rect = dom.canvas.getBoundingClientRect();
      const y = ((1 - state.peak.ndcY) / 2) * rect.height;
      return readBlock(view, rect.width / 2, Math.min(rect.height - 1, Math.max(0, y)));
    },
    update,
    describe() {
      const { peak, centre } = state;
      const setting = t('describeSetting', {
        camEl: shown('camEl'), sunEl: shown('sunEl'), roughness: shown('roughness'), nT: shown('nT'),
        fresnel: values.fresnel ? 'on' : 'off',
      });
      if (values.nT === 1) return `${setting} ${t('describeMatched', { diffuse: f3(peak.diffuse) })}`;
      // Concentrated: the brightest spot is at least three times as bright as a matte road reflecting the same share.
      const concentration = peak.specular / lambertianEquivalent(albedo, values.sunEl);
      const shape = concentration >= 3 ? t('shapeConcentrated', { concentration: fixed(concentration, 1) }) : t('shapeSpread');
      const ratio = albedo / SCENE.albedo;
      return `${setting} ${t('describe', {
        thetaD: deg(centre.thetaD),
        F: f3(centre.F),
        below: deg(peak.below),
        specular: f3(peak.specular),
        ratio: fixed(peak.specular / peak.diffuse, 1),
        diffuse: f3(peak.diffuse),
        total: times(growth.total),
        lobe: times(growth.lobe),
        fresnel: times(growth.fresnel),
        overall: times(growth.overall),
        albedo: percent(albedo),
        share: ratio < 0.95 ? 'less' : ratio <= 1.05 ? 'about' : 'more',
        albedoDiffuse: percent(SCENE.albedo),
        times: fixed(ratio, 2),
        shape,
      })}`;
    },
    csv() {
      const { column } = state;
      return {
        filename: `asphalt-cam${values.camEl}-sun${values.sunEl}-nT${values.nT}${values.fresnel ? '' : '-noF'}.csv`,
        columns: {
          ndc_y: column.map((c) => c.ndcY),
          distance_m: column.map((c) => c.distance),
          below_horizon_deg: column.map((c) => c.below),
          theta_d_deg: column.map((c) => c.thetaD),
          F: column.map((c) => c.F),
          L_specular: column.map((c) => c.specular),
          L_diffuse: column.map((c) => c.diffuse),
        },
      };
    },
    png: view ? () => view.toDataURL() : null,
    dispose() {
      resize.disconnect();
      stopReading();
      dom.canvas.removeEventListener('keydown', onKey);
      view?.dispose();
    },
  };
}
