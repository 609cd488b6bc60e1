// @ts-check
// Panel `fresnel-lighting`: a diffuse sphere under a shiny coat, k = mix(kd, ks, F) (lecture,
// "Fresnel reflection in lighting"), beside the same sphere with a constant weight w. Only the
// Fresnel sphere's rim turns toward ks. F is taken at the view angle N·V (for a mirror coat the
// half vector is N, so V·H = N·V). The lecture's mix is a heuristic; "Layered coat" shades the same
// sphere as a base under a clear coat (model.js), and a note says how the two differ. The GLSL
// under the picture is the file the shader includes.
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
import { lectureNote } from '../../ui/lectureNote.js';
import { fixed, rounded } from '../../ui/format.js';
import { definitionList } from '../../ui/definitionList.js';
import { coatConstants, diffuseSharesRgb } from './model.js';

const METHOD_NAMES = { exact: 'exact Fresnel', schlick: "Schlick's approximation", layered: 'the layered coat, exact F' };
const METHOD_CODES = { exact: 0, schlick: 1, layered: 2 };
const COAT_SOURCE = 'Kelemen & Szirmay-Kalos, Eurographics 2001 short papers; Weidlich & Wilkie, GRAPHITE 2007; '
  + 'Pharr, Jakob & Humphreys, Physically Based Rendering, 4th ed., §14.3 (CoatedDiffuse)';

export { schema };

/** The GLSL shown under the picture: the very chunk the shader compiles (#include <fresnel-lighting-mix>). */
export const MIX_GLSL = mixSource.trimEnd();
/** The sphere shader with the mix chunk put in: the same lines the panel shows. */
export const FRAGMENT = assembleShader(fragmentSource, { 'fresnel-lighting-mix': mixSource });
const RIM_DEG = 80; // the angle quoted for the rim

/** F at θ (degrees) on the Fresnel sphere, from the float64 reference (light from air into the coat). */
function weightAt(thetaDeg, nT, method) {
  const c = cosDeg(thetaDeg);
  return method === 'schlick' ? fresnelSchlick(c, 1, nT) : fresnelExact(c, 1, nT);
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
    uWeight: { value: 0.04 }, uMethod: { value: 0 }, uRi: { value: 0 }, uRe: { value: 0 },
  };
  const stage = createTwinStage(panel, {
    fragment: FRAGMENT,
    uniforms,
    onFrame: ctx.frameDrawn,
    ariaLabel: 'Two red spheres under a clear coat. On the first, the coat weight is the Fresnel factor F, so the rim '
      + 'turns toward the coat colour. On the second, a constant weight, so the rim stays the diffuse colour.',
    fallback: 'The spheres need WebGL2; the numbers and the GLSL below still apply.',
  });

  const summary = definitionList('fl-summary');
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
  const note = lectureNote(panel);
  panel.append(summary.element, plotHost, codeHead, pre);

  const plot = createLinePlot(plotHost, {
    xLabel: 'θ, the view angle between N and V', yLabel: 'Weight of ks', height: 260,
    series: [
      { label: 'F exact', stroke: '--c-exact' },
      { label: 'F Schlick', stroke: '--c-schlick', dash: [10, 6] },
      { label: 'Constant w', stroke: '--c-marker' },
    ],
  });
  const trace = addDielectricTrace(plotHost, plot, () => ({ nI: 1, nT: values.nT }), ['exact', 'schlick'],
    { exact: 'F exact', schlick: 'F Schlick' });

  const onCopy = async () => {
    copyStatus.textContent = await copyCode(MIX_GLSL, code);
  };
  copyButton.addEventListener('click', onCopy);

  const coat = ctx.gui.addFolder('Coat and comparison');
  ctx.bind(coat, ['nT', 'method', 'weight']);
  ctx.tie(coat.add({ match: () => ctx.set({ weight: rounded(normalIncidence(1, values.nT), 3) }) }, 'match')
    .name('Set w = F(0°) (centres match)'), ['weight']);
  ctx.bind(ctx.gui.addFolder('Colours and light'), ['kd', 'ks', 'lightAz', 'lightEl']);

  let curves = null;
  let curvesN = null;
  let layers = null; // ri and re of the coat (model.js)
  function update() {
    const { nT, method, weight } = values;
    if (nT !== curvesN) {
      curvesN = nT;
      curves = reflectanceCurves(1, nT);
      layers = coatConstants(nT);
      trace.refresh();
    }
    // Head-on under an overhead sun: how much of kd's diffuse light each model lets out, per channel.
    const shares = diffuseSharesRgb({ kd: hexToLinear(values.kd), cosV: 1, cosL: 1, n: nT, ri: layers.ri });
    const heuristic = 'The lecture\'s k = mix(kd, ks, F) is a heuristic: it weighs the diffuse layer by one F, taken at the view '
      + 'angle, although the light entered at the light\'s angle, and it loses nothing inside the coat. ';
    note.set(nT === 1 ? `${heuristic}With n = 1 the coat is no coat: it reflects nothing and traps nothing, and both models `
      + 'show the bare base.' : `${heuristic}A diffuse base `
      + `under a clear coat of n = ${nT} receives 1 − F(θl) of the sunlight, lets out 1 − F(θv) of what it reflects, `
      + `spread over a wider cone (1/n²), and the coat's underside sends ${fixed(layers.ri, 2)} of that diffuse light back `
      + `to the base. Head-on, under an overhead sun, the lecture's model lets out ${fixed(shares.lecture, 2)} of this kd's `
      + `diffuse light in every channel, the layered coat ${shares.layered.map((x) => fixed(x, 2)).join(', ')} `
      + `(red, green, blue), ${fixed(shares.layeredLuminance, 2)} of its luminance`
      + `${shares.layeredLuminance < shares.lecture
        ? ': the coated surface looks darker'
        : ': on a near-white base little of the light trapped under the coat is lost; it bounces until it leaves, a little '
          + 'more near the normal than from a bare Lambertian base (its radiance falls as 1 − F(θv) towards grazing), so head-on '
          + `the coat lets out more than the lecture's 1 − F${shares.layeredLuminance >= 1
            ? `, as much as the bare base or slightly more (${fixed(shares.layeredLuminance, 2)})` : ''}, `
          + `though over every direction at most 1 − F(θl) = ${fixed(shares.lecture, 2)}`}. `
      + `"Layered coat" shows it on the same sphere.`, COAT_SOURCE);
    plot.setData([curves.theta, curves.exact, curves.schlick, curves.theta.map(() => weight)]);
    plot.setMarks([thetaMark(RIM_DEG, `${RIM_DEG}°`)]);
    const rim = weightAt(RIM_DEG, nT, method);
    summary.set([
      ['F(0°) = R0', fixed(normalIncidence(1, nT), 4)],
      [`F(${RIM_DEG}°) ${method === 'schlick' ? 'Schlick' : 'exact'}`, fixed(rim, 4)],
      ['Constant w', `${fixed(weight, 3)} at every angle`],
      ...(method === 'layered' ? [
        ['Coat underside reflects', `${fixed(layers.ri, 4)} of diffuse light`],
        ['Diffuse let out head-on', `${fixed(shares.layeredLuminance, 3)} of its luminance (lecture: ${fixed(shares.lecture, 3)})`],
      ] : []),
    ]);
    const live = { exact: ['vec3 kExact '], schlick: ['vec3 kSchlick '], layered: ['float fV ', 'vec3 kLayered ', '  * albedo'] }[method];
    for (const line of lines) {
      line.classList.toggle('fl-live', [...live, 'vec3 kConstant '].some((start) => line.textContent.startsWith(start)));
    }
    stage.setLabels([
      method === 'layered' ? 'Layered coat, F exact' : `k = mix(kd, ks, F), F ${method === 'exact' ? 'exact' : 'Schlick'}`,
      `k = mix(kd, ks, ${fixed(weight, 3)})`,
    ]);
    if (!stage.view) return;
    uniforms.uKd.value = hexToLinear(values.kd); // the control's hex is sRGB; the shader lights in linear
    uniforms.uKs.value = hexToLinear(values.ks);
    uniforms.uN.value = nT;
    uniforms.uWeight.value = weight;
    uniforms.uMethod.value = METHOD_CODES[method];
    uniforms.uRi.value = layers.ri;
    uniforms.uRe.value = layers.re;
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
      const model = method === 'layered'
        ? `a diffuse base under a clear coat of n_t = ${nT} (the layered model: F at the light's and the view's angle, `
          + `the coat's underside reflecting ${fixed(layers.ri, 3)} of the diffuse light back)`
        : `k = mix(kd, ks, F), with F by ${METHOD_NAMES[method]} at the view angle N·V for a coat of n_t = ${nT}`;
      return `Fresnel sphere (first): ${model}: `
        + `F is ${fixed(weightAt(0, nT, method), 4)} at 0° and ${fixed(weightAt(RIM_DEG, nT, method), 4)} at ${RIM_DEG}°, `
        + 'so its rim turns toward ks. '
        + `Other sphere (second): a constant weight w = ${fixed(weight, 3)} at every angle, so its rim keeps the same mix as its centre.`;
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
