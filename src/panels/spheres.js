// Hero panel `spheres`: exact Fresnel vs Schlick on three spheres (exact, Schlick, error heatmap),
// one camera and light, with the live R(θ) plot below. Hovering a sphere marks that pixel's θ.
import { applyParams } from '../ui/params.js';
import { bindGui, createPanelGui } from '../ui/bindGui.js';
import { createRPlot } from '../ui/createRPlot.js';
import { colormapGradient } from '../ui/colormap.js';
import { downloadText, downloadUrl, toCsv } from '../ui/exporters.js';
import { createSphereTrio, directionFromAngles } from '../gl/createSphereTrio.js';
import { WebGL2Unavailable } from '../gl/createRenderer.js';
import { fresnelExact, fresnelSchlick, brewsterAngle, criticalAngle, normalIncidence } from '../optics/fresnel.js';
import { maxError, niceCeil, reflectanceCurves } from '../optics/curves.js';
import { indexPresets } from './indexPresets.js';
import { buildSpheresDom, formatAngle } from './spheresDom.js';
import { schema } from './spheresSchema.js';

export { schema };

export const id = 'spheres';
export const title = "Exact Fresnel vs Schlick's approximation";

const DEG = Math.PI / 180;

export function mount(host, { values, onChange = () => {} }) {
  const dom = buildSpheresDom(host);
  const plot = createRPlot(dom.plot);
  let trio = null;
  try {
    trio = createSphereTrio(dom.canvas, { onChange: onViewChange });
  } catch (error) {
    if (!(error instanceof WebGL2Unavailable)) throw error;
    dom.showStageMessage(`${error.message} The spheres need WebGL2; the plot below still works.`);
  }

  const gui = createPanelGui(dom.guiHost, 'Spheres: controls');
  const presets = indexPresets();
  const presetState = { matI: presets.idFor(values.nI), matT: presets.idFor(values.nT) };
  const optics = gui.addFolder('Indices of refraction');
  const presetI = optics.add(presetState, 'matI', presets.options).name('Incident side')
    .onChange((pid) => pid !== 'custom' && set({ nI: presets.index(pid) }));
  const presetT = optics.add(presetState, 'matT', presets.options).name('Sphere material')
    .onChange((pid) => pid !== 'custom' && set({ nT: presets.index(pid) }));
  const controllers = {
    ...bindGui(optics, schema, values, changed, ['nI', 'nT']),
  };
  optics.add({ swap: () => set({ nI: values.nT, nT: values.nI }) }, 'swap').name('Swap n_i ↔ n_t (look out of the glass)');
  const look = gui.addFolder('Look');
  Object.assign(controllers, bindGui(look, schema, values, changed, ['kd', 'ks', 'lightAz', 'lightEl', 'env', 'errScale']));
  const camera = gui.addFolder('Camera (or drag / arrow keys on the spheres)').close();
  Object.assign(controllers, bindGui(camera, schema, values, changed, ['viewAz', 'viewEl', 'viewDist']));

  let curvesKey = '';
  let curves = null;
  let errScale = 0.05;

  function changed() {
    update();
    onChange({ ...values });
  }

  function onViewChange(view) {
    values.viewAz = Math.round(view.azimuth * 10) / 10;
    values.viewEl = Math.round(view.elevation * 10) / 10;
    values.viewDist = Math.round(view.distance * 100) / 100;
    for (const key of ['viewAz', 'viewEl', 'viewDist']) controllers[key].updateDisplay();
    onChange({ ...values });
  }

  function update() {
    const { nI, nT } = values;
    const key = `${nI}|${nT}`;
    if (key !== curvesKey) {
      curvesKey = key;
      curves = reflectanceCurves(nI, nT);
      const critical = criticalAngle(nI, nT);
      const brewster = brewsterAngle(nI, nT) / DEG;
      plot.setCurves(curves, { brewster, critical: critical === null ? null : critical / DEG });
      const worst = maxError(curves);
      dom.setSummary([
        ['R0', normalIncidence(nI, nT).toFixed(5)],
        ['Brewster', formatAngle(brewster)],
        ['Critical', critical === null ? 'none (n_i ≤ n_t)' : formatAngle(critical / DEG)],
        ['Max |exact − Schlick|', `${worst.value.toFixed(4)} at ${formatAngle(worst.theta)}`],
      ]);
    }
    errScale = values.errScale === 'auto' ? niceCeil(maxError(curves).value) : Number(values.errScale);
    dom.setLegend(errScale, colormapGradient());
    presetState.matI = presets.idFor(nI);
    presetState.matT = presets.idFor(nT);
    presetI.updateDisplay();
    presetT.updateDisplay();
    if (trio) {
      const view = trio.view;
      if (view.azimuth !== values.viewAz || view.elevation !== values.viewEl || view.distance !== values.viewDist) {
        trio.setView({ azimuth: values.viewAz, elevation: values.viewEl, distance: values.viewDist });
      }
      trio.setParams({
        nI, nT, kd: values.kd, ks: values.ks, envStrength: values.env, errScale,
        sunDir: directionFromAngles(values.lightAz, values.lightEl),
      });
    }
  }

  // Hovering a sphere: its θ on the plot and the numbers at that pixel.
  const onHover = (event) => {
    const hit = trio?.pick(event.clientX, event.clientY);
    if (!hit) return onLeave();
    const theta = Math.acos(hit.cosTheta) / DEG;
    const exact = fresnelExact(hit.cosTheta, values.nI, values.nT);
    const schlick = fresnelSchlick(hit.cosTheta, values.nI, values.nT);
    dom.setReadout({ theta, exact, schlick, error: Math.abs(exact - schlick) });
    plot.setHover(theta);
  };
  const onLeave = () => {
    dom.setReadout(null);
    plot.setHover(null);
  };
  dom.canvas.addEventListener('pointermove', onHover);
  dom.canvas.addEventListener('pointerleave', onLeave);

  function set(update) {
    const result = applyParams(schema, values, update);
    for (const key of Object.keys(result.applied)) controllers[key]?.updateDisplay();
    if (Object.keys(result.applied).length) changed();
    return result;
  }

  function exportCsv() {
    const { theta, exact, schlick, s, p, error } = curves;
    downloadText(`fresnel-nI${values.nI}-nT${values.nT}.csv`,
      toCsv({ theta_deg: theta, R_exact: exact, R_schlick: schlick, Rs: s, Rp: p, abs_error: error }));
  }

  function exportPng() {
    if (trio) downloadUrl(`fresnel-spheres-nI${values.nI}-nT${values.nT}.png`, trio.toDataURL());
  }

  dom.onExport({ csv: exportCsv, png: trio ? exportPng : null });
  update();

  return {
    values,
    set,
    get curves() { return curves; },
    get errScale() { return errScale; },
    trio,
    plot,
    exportCsv,
    exportPng,
    dispose() {
      dom.canvas.removeEventListener('pointermove', onHover);
      dom.canvas.removeEventListener('pointerleave', onLeave);
      trio?.dispose();
      plot.dispose();
      gui.destroy();
      host.replaceChildren();
    },
  };
}
