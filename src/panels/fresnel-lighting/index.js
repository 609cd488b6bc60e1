// @ts-check
// Panel `fresnel-lighting`: a diffuse sphere under a shiny coat, k = mix(kd, ks, F) (lecture,
// "Fresnel reflection in lighting"), beside the same sphere with a constant weight w. Only the
// Fresnel sphere's rim turns toward ks. F is taken at the view angle N·V (for a mirror coat the
// half vector is N, so V·H = N·V). The lecture's mix is a heuristic; "Layered coat" shades the same
// sphere as a base under a clear coat (physics.js), and a note says how the two differ. The GLSL
// under the picture is the file the shader includes.
import { hexToLinear } from '../../ui/srgb.js';
import { assembleShader } from '../../gl/shaderChunks.js';
import { reflectanceCurves } from '../../optics/curves.js';
import { normalIncidence } from '../../optics/fresnel.js';
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
import { angle, fixed, rounded } from '../../ui/format.js';
import { definitionList } from '../../ui/definitionList.js';
import { coatConstants, diffuseSharesRgb } from './physics.js';
import { indexText } from '../shared/indexText.js';
import { RIM_DEG, describeSpheres, weightAt } from './words.js';
import english from 'virtual:messages/en/fresnel-lighting';
import { messages } from '../../i18n/messages.js';

const t = messages('fresnel-lighting', english);
const METHOD_CODES = { exact: 0, schlick: 1, layered: 2 };

export { schema };

/** The GLSL shown under the picture: the very chunk the shader compiles (#include <fresnel-lighting-mix>). */
export const MIX_GLSL = mixSource.trimEnd();
/** The sphere shader with the mix chunk put in: the same lines the panel shows. */
export const FRAGMENT = assembleShader(fragmentSource, { 'fresnel-lighting-mix': mixSource });

/** Copies text; where the clipboard API is refused, selects the code so Ctrl+C works. */
async function copyCode(text, codeElement) {
  try {
    await navigator.clipboard.writeText(text);
    return t('copied');
  } catch {
    const range = document.createRange();
    range.selectNodeContents(codeElement);
    const selection = window.getSelection();
    selection.removeAllRanges();
    selection.addRange(range);
    return document.execCommand?.('copy') ? t('copied') : t('selected');
  }
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
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
    ariaLabel: t('stage'),
    fallback: t('noWebgl'),
  });

  const summary = definitionList('fl-summary');
  const plotHost = el('div', 'fl-plot');
  plotHost.setAttribute('aria-label', t('plot'));
  const codeHead = el('div', 'fl-code-head');
  const copyButton = el('button', 'fl-copy', t('copy'));
  copyButton.type = 'button';
  const copyStatus = el('span', 'fl-copy-status');
  copyStatus.setAttribute('role', 'status');
  codeHead.append(el('h3', '', t('codeHead')), copyButton, copyStatus);
  const pre = makeScrollBox(el('pre'), t('code'));
  const code = el('code', 'language-glsl');
  const lines = MIX_GLSL.split('\n').map((line) => el('span', '', line));
  lines.forEach((line, i) => code.append(...(i ? ['\n', line] : [line])));
  pre.append(code);
  const note = lectureNote(panel);
  panel.append(summary.element, plotHost, codeHead, pre);

  const plot = createLinePlot(plotHost, {
    xLabel: t('xLabel'), yLabel: t('yLabel'), height: 260,
    series: [
      { label: t('seriesExact'), stroke: '--c-exact' },
      { label: t('seriesSchlick'), stroke: '--c-schlick', dash: [10, 6] },
      { label: t('constant'), stroke: '--c-marker' },
    ],
  });
  const trace = addDielectricTrace(plotHost, plot, () => ({ nI: 1, nT: values.nT }), ['exact', 'schlick'],
    { exact: t('seriesExact'), schlick: t('seriesSchlick') });

  const onCopy = async () => {
    copyStatus.textContent = await copyCode(MIX_GLSL, code);
  };
  copyButton.addEventListener('click', onCopy);

  const coat = ctx.gui.addFolder(t('folderCoat'));
  ctx.bind(coat, ['nT', 'method', 'weight']);
  ctx.tie(coat.add({ match: () => ctx.set({ weight: rounded(normalIncidence(1, values.nT), 3) }) }, 'match')
    .name(t('match')), ['weight']);
  ctx.bind(ctx.gui.addFolder(t('folderLight')), ['kd', 'ks', 'lightAz', 'lightEl']);

  let curves = null;
  let curvesN = null;
  let layers = null; // ri and re of the coat (physics.js)
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
    const [r, g, b] = shares.layered.map((x) => fixed(x, 2));
    const outcome = shares.layeredLuminance < shares.lecture ? 'darker' : shares.layeredLuminance >= 1 ? 'more' : 'lighter';
    note.set(t('note', {
      coat: nT === 1 ? 'none' : 'clear', schlick: method === 'schlick' ? 'yes' : 'no', n: indexText(nT), ri: fixed(layers.ri, 2),
      lecture: fixed(shares.lecture, 2),
      layered: t('rgb', { r, g, b }), luminance: fixed(shares.layeredLuminance, 2), outcome,
    }), t('noteSource'));
    plot.setData([curves.theta, curves.exact, curves.schlick, curves.theta.map(() => weight)]);
    plot.setMarks([thetaMark(RIM_DEG, angle(RIM_DEG, 0))]);
    const rim = weightAt(RIM_DEG, nT, method);
    summary.set([
      [t('r0'), fixed(normalIncidence(1, nT), 4)],
      [t('rim', { angle: angle(RIM_DEG, 0), method }), fixed(rim, 4)],
      [t('constant'), t('constantValue', { w: fixed(weight, 3) })],
      ...(method === 'layered' ? [
        [t('underside'), t('undersideValue', { ri: fixed(layers.ri, 4) })],
        [t('letOut'), t('letOutValue', { layered: fixed(shares.layeredLuminance, 3), lecture: fixed(shares.lecture, 3) })],
      ] : []),
    ]);
    const live = { exact: ['vec3 kExact '], schlick: ['vec3 kSchlick '], layered: ['float fV ', 'vec3 kLayered ', '  * albedo'] }[method];
    for (const line of lines) {
      line.classList.toggle('fl-live', [...live, 'vec3 kConstant '].some((start) => line.textContent.startsWith(start)));
    }
    stage.setLabels([
      method === 'layered' ? t('labelLayered') : t('labelMix', { method }),
      t('labelConstant', { w: fixed(weight, 3) }),
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
      return describeSpheres(values, layers.ri);
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
