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
import { fixed } from '../../ui/format.js';
import {
  SCENE, brightestSightLine, cameraBasis, highlightInView, pixelRay, shadeRoad, sheenGrowth, specularAlbedo, sunDirection,
} from './physics.js';
import { describeRoad, readoutText, summaryRows } from './words.js';
import { buildAsphaltDom } from './buildAsphaltDom.js';
import fragment from './asphalt.frag.glsl?raw';
import { schema } from './schema.js';

export { schema };

const t = messages('asphalt', english);

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
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
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
  let brightest = { below: 0, specular: 0 };
  let road = null; // what the words are made of (words.js)

  function update() {
    state = highlightInView(values, aspect());
    const r0 = normalIncidence(1, values.nT);
    const key = [values.sunEl, values.roughness, values.nT, values.fresnel].join();
    if (key !== sunKey) {
      sunKey = key;
      albedo = specularAlbedo(values);
      brightest = brightestSightLine(values);
    }
    road = { values, peak: state.peak, centre: state.centre, growth: sheenGrowth(values, aspect()), albedo, brightest };
    dom.setBadge(values.fresnel ? t('badgeOn') : t('badgeOff', { r0: fixed(r0, 3) }), values.fresnel);
    dom.setSummary(summaryRows(road));
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
    dom.setReadout(readoutText(shadeRoad(pixelRay(values.camEl, ndcX, ndcY, rect.width / rect.height), values)));
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
      return describeRoad(road);
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
