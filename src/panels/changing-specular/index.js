// @ts-check
// Panel `changing-specular`: Phong's highlight (v·r)^s only asks how close the view is to the mirror
// direction, never how the light meets the surface (lecture, "Changing Specular"). The same floor
// is lit both ways side by side, with a cross-section of the vectors and a plot of the peak highlight
// against elevation: plain Phong (k_s = R0) is flat, Phong × F rises towards grazing.
// Numbers: src/optics/phong.js (float64); picture: changing-specular.frag.glsl.
import english from 'virtual:messages/en/changing-specular';
import { messages } from '../../i18n/messages.js';
import { createShaderView } from '../../gl/createShaderView.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { thetaMark } from '../../ui/plotMarks.js';
import { DEG } from '../../optics/angles.js';
import { peakHighlightCurves, phongHighlights } from '../../optics/phong.js';
import { startWebGL } from '../shared/startWebGL.js';
import { angle, fixed, tickLabel } from '../../ui/format.js';
import { buildChangingSpecularDom } from './buildChangingSpecularDom.js';
import fragment from './changing-specular.frag.glsl?raw';
import { schema } from './schema.js';
import { stackOnPhone } from '../shared/stackOnPhone.js';

export { schema };

const t = messages('changing-specular', english);

const SCENE = { fovY: 40, cameraDist: 4, light: 6, exposure: 1 };

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  /** A control's value as it is written in a sentence: the decimals of its step, in the page's language. */
  const shown = (key) => tickLabel(values[key], schema[key].step);
  const dom = buildChangingSpecularDom(root);
  const view = startWebGL(dom.stage, () => createShaderView(dom.canvas, {
    fragment,
    onFrame: ctx.frameDrawn,
    cache: { live: ['uN'] }, // the index redraws only k (changing-specular.frag.glsl)
    uniforms: {
      uViewEl: { value: 0.5 }, uSunDir: { value: [0, 0.5, 0.87] }, uS: { value: 60 }, uN: { value: 1.5 },
      uTanHalfFov: { value: Math.tan((SCENE.fovY / 2) * DEG) }, uCameraDist: { value: SCENE.cameraDist },
      uLight: { value: SCENE.light }, uExposure: { value: SCENE.exposure }, uStacked: { value: 0 },
    },
  }), t('noWebgl'));
  // On a phone the two floors stand one above the other, each as wide as the screen.
  const layout = stackOnPhone(dom.stage, 'cspec-stacked', view);
  const plot = createLinePlot(dom.plot, {
    xLabel: t('plot.x'),
    xShort: t('plot.xShort'),
    yLabel: t('plot.y'),
    yRange: [0, 1],
    height: 260,
    digits: 4,
    series: [
      { label: t('plot.phong'), stroke: '--c-schlick', width: 3.5 },
      { label: t('plot.phongF'), stroke: '--c-exact', width: 3.5 },
    ],
  });

  let curves = null;
  let curvesN = null;
  let highlight = null;

  // Linked: moving either elevation moves the other, so the view stays in the mirror direction.
  // The change that makes them agree, or null.
  function linkUpdate(keys) {
    if (!values.linked || values.viewEl === values.lightEl) return null;
    return keys.includes('viewEl') && !keys.includes('lightEl') ? { lightEl: values.viewEl } : { viewEl: values.lightEl };
  }

  const opening = linkUpdate([]); // linked, but the link gave two elevations: the view takes the light's
  if (opening) ctx.set(opening);
  ctx.bind(ctx.gui.addFolder(t('folder.lightView')), ['lightEl', 'viewEl', 'linked']);
  ctx.bind(ctx.gui.addFolder(t('folder.surface')), ['s', 'nT']);

  function update(keys = []) {
    const link = linkUpdate(keys);
    // The host runs update again with the followed key: that draws, not this one. Where a deck
    // has locked the other elevation the link cannot hold, and this one draws what there is.
    if (link && !ctx.set(link).refused) return;
    if (curvesN !== values.nT) {
      curvesN = values.nT;
      curves = peakHighlightCurves(1, values.nT);
      plot.setData([curves.elevation, curves.phong, curves.phongF]);
    }
    highlight = phongHighlights(values.lightEl, values.viewEl, values.s, 1, values.nT);
    plot.setMarks([thetaMark(values.lightEl, t('plot.light', { elevation: shown('lightEl') }))]);
    dom.setDiagram(values.lightEl, values.viewEl, values.s);
    dom.setNumbers(highlight, values.s);
    if (view) {
      const u = view.uniforms;
      u.uViewEl.value = values.viewEl * DEG;
      u.uSunDir.value = [0, Math.sin(values.lightEl * DEG), Math.cos(values.lightEl * DEG)];
      u.uS.value = values.s;
      u.uN.value = values.nT;
      view.render();
    }
  }
  update();

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
      return t('describe', {
        light: shown('lightEl'),
        view: shown('viewEl'),
        s: shown('s'),
        nT: shown('nT'),
        vDotR: fixed(h.vDotR, 3),
        phong: fixed(h.phong, 4),
        r0: fixed(h.R0, 4),
        phongF: fixed(h.phongF, 4),
        theta: angle(h.thetaDeg, 1),
        F: fixed(h.F, 4),
        at80: fixed(curveAt('phongF', 80), 4),
        at5: fixed(curveAt('phongF', 5), 4),
      });
    },
    csv() {
      return {
        filename: `changing-specular-nT${values.nT}.csv`,
        columns: { elevation_deg: curves.elevation, phong_ks_R0: curves.phong, phong_times_F: curves.phongF },
      };
    },
    png: view ? () => view.toDataURL() : null,
    dispose() {
      layout.dispose();
      view?.dispose();
      plot.dispose();
    },
  };
}
