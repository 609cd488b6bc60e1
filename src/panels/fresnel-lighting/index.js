// @ts-check
// Panel `fresnel-lighting`: a diffuse sphere under a shiny coat, k = mix(kd, ks, F) (lecture,
// "Fresnel reflection in lighting"), beside the same sphere with a constant weight w. Only the
// Fresnel sphere's rim turns toward ks. F is taken at the view angle N·V (for a mirror coat the
// half vector is N, so V·H = N·V). The GLSL under the picture is the file the shader includes.
import { hexToLinear } from '../../ui/srgb.js';
import { assembleShader } from '../../gl/shaderChunks.js';
import { cosDeg } from '../../optics/angles.js';
import { reflectanceCurves } from '../../optics/curves.js';
import { fresnelExact, fresnelSchlick, normalIncidence } from '../../optics/fresnel.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { el } from '../../ui/el.js';
import { thetaMark } from '../../ui/plotMarks.js';
import { createTwinStage } from '../shared/createTwinStage.js';
import fragmentSource from './fresnel-lighting.frag.glsl?raw';
import mixSource from './fresnel-lighting-mix.glsl?raw';
import './styles.css';
import { schema } from './schema.js';
import { addDielectricTrace } from '../shared/dielectricTrace.js';
import { makeScrollBox } from '../../ui/scrollBox.js';

const METHOD_NAMES = { exact: 'exact Fresnel', schlick: "Schlick's approximation" };

export { schema };

/** The GLSL shown under the picture: the very chunk the shader compiles (#include <fresnel-lighting-mix>). */
export const MIX_GLSL = mixSource.trimEnd();
/** The sphere shader with the mix chunk put in: the same lines the panel shows. */
export const FRAGMENT = assembleShader(fragmentSource, { 'fresnel-lighting-mix': mixSource });
const RIM_DEG = 80; // the angle quoted for the rim

/** F at θ (degrees) on the Fresnel sphere, from the float64 reference (light from air into the coat). */
function weightAt(thetaDeg, nT, method) {
  const c = cosDeg(thetaDeg);
  return method === 'exact' ? fresnelExact(c, 1, nT) : fresnelSchlick(c, 1, nT);
}

/** Copies text; where the clipboard API is refused, selects the code so Ctrl+C works. */
async function copyCode(text, codeElement) {
  try {
    await navigator.clipboard.writeText(text);
    return 'Copied';
  } catch {
    const range = document.createRange();
    range.selectNodeContents(codeElement);
    const selection = window.getSelection();
    selection.removeAllRanges();
    selection.addRange(range);
    return document.execCommand?.('copy') ? 'Copied' : 'Selected: press Ctrl+C to copy';
  }
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'fl-panel');
  root.append(panel);
  const uniforms = {
    uKd: { value: [0, 0, 0] }, uKs: { value: [0, 0, 0] }, uN: { value: 1.5 },
    uWeight: { value: 0.04 }, uMethod: { value: 0 },
  };
  const stage = createTwinStage(panel, {
    fragment: FRAGMENT,
    uniforms,
    onFrame: ctx.frameDrawn,
    ariaLabel: 'Two red spheres under a clear coat. On the first, the coat weight is the Fresnel factor F, so the rim '
      + 'turns toward the coat colour. On the second, a constant weight, so the rim stays the diffuse colour.',
    fallback: 'The spheres need WebGL2; the numbers and the GLSL below still apply.',
  });

  const summary = el('dl', 'fl-summary');
  const plotHost = el('div', 'fl-plot');
  plotHost.setAttribute('aria-label', 'Weight of ks against the view angle θ: Fresnel and constant');
  const codeHead = el('div', 'fl-code-head');
  const copyButton = el('button', 'fl-copy', 'Copy GLSL');
  copyButton.type = 'button';
  const copyStatus = el('span', 'fl-copy-status');
  copyStatus.setAttribute('role', 'status');
  codeHead.append(el('h3', '', 'The GLSL (as compiled here)'), copyButton, copyStatus);
  const pre = makeScrollBox(el('pre'), 'The GLSL');
  const code = el('code', 'language-glsl');
  const lines = MIX_GLSL.split('\n').map((line) => el('span', '', line));
  lines.forEach((line, i) => code.append(...(i ? ['\n', line] : [line])));
  pre.append(code);
  panel.append(summary, plotHost, codeHead, pre);

  const plot = createLinePlot(plotHost, {
    xLabel: 'θ, the view angle between N and V', yLabel: 'Weight of ks', height: 260,
    series: [
      { label: 'F exact', stroke: '--c-exact' },
      { label: 'F Schlick', stroke: '--c-schlick', dash: [10, 6] },
      { label: 'Constant w', stroke: '--c-marker' },
    ],
  });
  const trace = addDielectricTrace(plotHost, plot, () => ({ nI: 1, nT: values.nT }), ['exact', 'schlick'], { exact: 'F exact', schlick: 'F Schlick' });

  const onCopy = async () => {
    copyStatus.textContent = await copyCode(MIX_GLSL, code);
  };
  copyButton.addEventListener('click', onCopy);

  const coat = ctx.gui.addFolder('Coat and comparison');
  ctx.bind(coat, ['nT', 'method', 'weight']);
  ctx.tie(coat.add({ match: () => ctx.set({ weight: Number(normalIncidence(1, values.nT).toFixed(3)) }) }, 'match')
    .name('Set w = F(0°) (centres match)'), ['weight']);
  ctx.bind(ctx.gui.addFolder('Colours and light'), ['kd', 'ks', 'lightAz', 'lightEl']);

  let curves = null;
  let curvesN = null;
  function update() {
    const { nT, method, weight } = values;
    if (nT !== curvesN) {
      curvesN = nT;
      curves = reflectanceCurves(1, nT);
      trace.refresh();
    }
    plot.setData([curves.theta, curves.exact, curves.schlick, curves.theta.map(() => weight)]);
    plot.setMarks([thetaMark(RIM_DEG, `${RIM_DEG}°`)]);
    const rim = weightAt(RIM_DEG, nT, method);
    summary.replaceChildren(...[
      ['F(0°) = R0', normalIncidence(1, nT).toFixed(4)],
      [`F(${RIM_DEG}°) ${method === 'exact' ? 'exact' : 'Schlick'}`, rim.toFixed(4)],
      ['Constant w', `${weight.toFixed(3)} at every angle`],
    ].map(([term, value]) => {
      const wrap = el('div');
      wrap.append(el('dt', '', term), el('dd', '', value));
      return wrap;
    }));
    const live = method === 'exact' ? 'kExact' : 'kSchlick';
    for (const line of lines) line.classList.toggle('fl-live', line.textContent.startsWith(`vec3 ${live} `) || line.textContent.startsWith('vec3 kConstant '));
    stage.setLabels([`k = mix(kd, ks, F), F ${method === 'exact' ? 'exact' : 'Schlick'}`, `k = mix(kd, ks, ${weight.toFixed(3)})`]);
    if (!stage.view) return;
    uniforms.uKd.value = hexToLinear(values.kd); // the control's hex is sRGB; the shader lights in linear
    uniforms.uKs.value = hexToLinear(values.ks);
    uniforms.uN.value = nT;
    uniforms.uWeight.value = weight;
    uniforms.uMethod.value = method === 'exact' ? 0 : 1;
    stage.setLight(values.lightAz, values.lightEl);
    stage.render();
  }
  update();

  return {
    stage,
    plot,
    code: MIX_GLSL,
    update,
    describe() {
      const { nT, method, weight } = values;
      return `Fresnel sphere (first): k = mix(kd, ks, F), with F by ${METHOD_NAMES[method]} at the view angle N·V for a coat of n_t = ${nT}: `
        + `F is ${weightAt(0, nT, method).toFixed(4)} at 0° and ${weightAt(RIM_DEG, nT, method).toFixed(4)} at ${RIM_DEG}°, so its rim turns toward ks. `
        + `Other sphere (second): a constant weight w = ${weight.toFixed(3)} at every angle, so its rim keeps the same mix as its centre.`;
    },
    csv() {
      return {
        filename: `fresnel-lighting-nT${values.nT}.csv`,
        columns: {
          theta_deg: curves.theta, F_exact: curves.exact, F_schlick: curves.schlick,
          w_constant: curves.theta.map(() => values.weight),
        },
      };
    },
    png: stage.view ? () => stage.view.toDataURL() : null,
    trace,
    dispose() {
      copyButton.removeEventListener('click', onCopy);
      trace.dispose();
      plot.dispose();
      stage.dispose();
    },
  };
}
