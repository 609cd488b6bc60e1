// Panel `changing-specular`: Phong's highlight (v·r)^s only asks how close the view is to the mirror
// direction, never how the light meets the surface (lecture, "Changing Specular"). The same floor
// is lit both ways side by side, with a cross-section of the vectors and a plot of the peak highlight
// against elevation: plain Phong (k_s = R0) is flat, Phong × F rises towards grazing.
// Numbers: src/optics/phong.js (float64); picture: shaders/changing-specular.frag.glsl.
import { createShaderView } from '../gl/createShaderView.js';
import { WebGL2Unavailable } from '../gl/createRenderer.js';
import { createLinePlot } from '../ui/createLinePlot.js';
import { peakHighlightCurves, phongHighlights } from '../optics/phong.js';
import { buildChangingSpecularDom } from './changing-specularDom.js';

export const id = 'changing-specular';
export const title = 'Changing specular';
export const usesWebGL = true;
export const materialParam = 'n';

export const schema = {
  lightEl: { type: 'number', default: 30, min: 1, max: 90, step: 0.5, label: 'Light elevation °' },
  viewEl: { type: 'number', default: 30, min: 1, max: 90, step: 0.5, label: 'View elevation °' },
  linked: { type: 'boolean', default: true, label: 'View follows light (mirror)' },
  s: { type: 'number', default: 60, min: 1, max: 500, step: 1, label: 'Phong exponent s' },
  n: { type: 'number', default: 1.5, min: 1, max: 3, step: 0.001, label: 'Refractive index n' },
};

const DEG = Math.PI / 180;
const SCENE = { fovY: 40, cameraDist: 4, light: 6, exposure: 1 };

export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildChangingSpecularDom(root);
  let view = null;
  try {
    view = createShaderView(dom.canvas, {
      fragment: 'changing-specular.frag',
      onFrame: ctx.frameDrawn,
      uniforms: {
        uViewEl: { value: 0.5 }, uSunDir: { value: [0, 0.5, 0.87] }, uS: { value: 60 }, uN: { value: 1.5 },
        uTanHalfFov: { value: Math.tan((SCENE.fovY / 2) * DEG) }, uCameraDist: { value: SCENE.cameraDist },
        uLight: { value: SCENE.light }, uExposure: { value: SCENE.exposure },
      },
    });
  } catch (error) {
    if (!(error instanceof WebGL2Unavailable)) throw error;
    dom.showStageMessage(`${error.message} The floors need WebGL2; the diagram and plot below still work.`);
  }
  const plot = createLinePlot(dom.plot, {
    xLabel: 'Elevation of light and view (mirror), °',
    yLabel: 'Peak highlight',
    yRange: [0, 1],
    height: 260,
    digits: 4,
    series: [
      { label: 'Phong, k_s = R0', stroke: '--c-schlick', width: 3.5 },
      { label: 'Phong × F', stroke: '--c-exact', width: 3.5 },
    ],
  });

  let curves = null;
  let curvesN = null;
  let highlight = null;
  let mounted = false;

  // Linked: moving either elevation moves the other, so the view stays in the mirror direction.
  // Returns the key it moved, or null.
  function linkElevations(keys) {
    if (!values.linked || values.viewEl === values.lightEl) return null;
    const follow = keys.includes('viewEl') && !keys.includes('lightEl') ? 'lightEl' : 'viewEl';
    values[follow] = follow === 'viewEl' ? values.lightEl : values.viewEl;
    return follow;
  }

  linkElevations([]); // linked, but the link gave two elevations: the view takes the light's
  ctx.bind(ctx.gui.addFolder('Light and view'), ['lightEl', 'viewEl', 'linked']);
  ctx.bind(ctx.gui.addFolder('Surface'), ['s', 'n']);

  function update(keys = []) {
    const moved = linkElevations(keys);
    if (curvesN !== values.n) {
      curvesN = values.n;
      curves = peakHighlightCurves(1, values.n);
      plot.setData([curves.elevation, curves.phong, curves.phongF]);
    }
    highlight = phongHighlights(values.lightEl, values.viewEl, values.s, 1, values.n);
    plot.setMarks([{ x: values.lightEl, color: '--c-marker', label: `light ${values.lightEl}°` }]);
    dom.setDiagram(values.lightEl, values.viewEl, values.s);
    dom.setNumbers(highlight, values.s);
    if (view) {
      const u = view.uniforms;
      u.uViewEl.value = values.viewEl * DEG;
      u.uSunDir.value = [0, Math.sin(values.lightEl * DEG), Math.cos(values.lightEl * DEG)];
      u.uS.value = values.s;
      u.uN.value = values.n;
      view.render();
    }
    if (moved && mounted) ctx.changed([moved]); // the host updates that control and the URL
  }
  update();
  mounted = true;

  /** The value of a plotted curve at an elevation (degrees), for tests and the description. */
  const curveAt = (name, elevation) => curves[name][curves.elevation.indexOf(elevation)];

  return {
    view,
    plot,
    get curves() { return curves; },
    get highlight() { return highlight; },
    curveAt,
    update,
    describe() {
      const h = highlight;
      return `Light ${values.lightEl}° and view ${values.viewEl}° above the surface, s = ${values.s}, n = ${values.n}. `
        + `At the centre of view v·r = ${h.vDotR.toFixed(3)}: plain Phong gives ${h.phong.toFixed(4)} (k_s = R0 = ${h.R0.toFixed(4)}), `
        + `Phong × F gives ${h.phongF.toFixed(4)} (F at θ = ${h.thetaDeg.toFixed(1)}° is ${h.F.toFixed(4)}). `
        + `At the mirror peak plain Phong is ${h.R0.toFixed(4)} at every elevation, while Phong × F is `
        + `${curveAt('phongF', 80).toFixed(4)} at 80° and ${curveAt('phongF', 5).toFixed(4)} at 5°.`;
    },
    csv() {
      return {
        filename: `changing-specular-n${values.n}.csv`,
        columns: { elevation_deg: curves.elevation, phong_ks_R0: curves.phong, phong_times_F: curves.phongF },
      };
    },
    png: view ? () => view.toDataURL() : null,
    dispose() {
      view?.dispose();
      plot.dispose();
    },
  };
}
