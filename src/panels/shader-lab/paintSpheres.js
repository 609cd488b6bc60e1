// Two spheres shaded with Fresnel: the first with the student's function, the second with the exact one
// (the lab's exact answer, renamed so the two can sit in one shader), under the lab's sky
// and sun, as in the fresnel-lighting and metals panels: a coated diffuse sphere
// k = mix(kd, ks, F) for a dielectric (lecture, "Fresnel Reflection in Lighting"), the reflected
// sky tinted by F for a conductor. Drawn by the grading context into its own canvas and copied to
// a 2D canvas on the page, so the panel holds one WebGL context, not two.
import { assembleShader } from '../../gl/shaderChunks.js';
import { createProgram } from '../../gl/createProgram.js';
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { DEG } from '../../optics/angles.js';
import { STAGE_CAMERA } from '../shared/createTwinStage.js';
import { WRAPPER_LINE } from './studentShader.js';
import { exactReference } from './exercises.js';
import { phoneWidth } from '../../ui/phoneWidth.js';

const COAT_INDEX = 1.5;
const KD = [0.55, 0.09, 0.05]; // linear RGB of the diffuse layer (a red paint)

const STUDENT = '// <the student’s code>';

/**
 * The fragment (without #version): the page's chunks resolved first, then the student's code
 * spliced in after #line 1 (so nothing in it is read as an #include), the exact function after it.
 */
export function sphereFragment(code, exercise) {
  const conductor = exercise.kind === 'conductor';
  const name = conductor ? 'fresnelConductor' : 'fresnel';
  const reference = exactReference(exercise).replace(new RegExp(`\\b${name}\\b`, 'g'), `lab_reference_${name}`);
  const shade = conductor
    ? `vec3 F = hit.side == 0 ? fresnelConductor(nv, uMetalN, uMetalK) : lab_reference_fresnelConductor(nv, uMetalN, uMetalK);
  vec3 k = F * environment(reflect(-V, N));`
    : `float F = hit.side == 0 ? fresnel(nv, 1.0, uN) : lab_reference_fresnel(nv, 1.0, uN);
  vec3 kd = uKd * (max(dot(N, normalize(uSunDir)), 0.0) + 0.3 * skyLight(N));
  vec3 k = mix(kd, environment(reflect(-V, N)), F);`;
  const page = assembleShader(`precision highp float;
#include <environment>
#include <color>
#include <twinStage>
uniform float uN;
uniform vec3 uKd;
uniform vec3 uMetalN;
uniform vec3 uMetalK;
out vec4 fragColor;
#line 1
${STUDENT}
#line ${WRAPPER_LINE}
${reference}
void main() {
  StageHit hit = castStage();
  if (!hit.found) {
    fragColor = vec4(linearToSrgb(environment(hit.dir)), 1.0);
    return;
  }
  vec3 N = hit.normal;
  vec3 V = hit.view;
  float nv = dot(N, V);
  ${shade}
  fragColor = vec4(linearToSrgb(k), 1.0);
}`);
  return page.replace(STUDENT, () => code);
}

/**
 * Paints both spheres for `code` into `target` (a 2D canvas, sized by its CSS box). The program
 * is compiled once per code; throws ShaderError (shaderError.js) when it does not compile.
 */
export function createSpherePainter(gl) {
  let program = null;
  let programKey = null;
  return {
    /** Throws ShaderError when the code does not compile beside the page's lighting code (not retried until it changes). */
    paint(target, code, exercise, metal) {
      const key = `${exercise.kind}|${code}`;
      if (key !== programKey) {
        program?.dispose();
        program = null;
        programKey = key;
        program = createProgram(gl, sphereFragment(code, exercise));
      }
      if (!program) return;
      // On a phone one sphere above the other (the twin stage's uStacked), each in a 4:3 half.
      const stacked = phoneWidth().matches;
      target.parentElement?.classList.toggle('twin-stacked', stacked);
      const box = target.getBoundingClientRect();
      const ratio = Math.min(2, window.devicePixelRatio || 1);
      const width = Math.max(2, Math.round((box.width || 640) * ratio));
      const height = Math.max(1, Math.round(stacked ? width * 1.5 : width / 2));
      const canvas = /** @type {HTMLCanvasElement} */ (gl.canvas);
      if (canvas.width !== width || canvas.height !== height) Object.assign(canvas, { width, height });
      const { distance, fovDeg, elevationDeg } = STAGE_CAMERA;
      program.setUniforms({
        uResolution: { value: [width, height] },
        uCamera: { value: [distance, 1 / Math.tan((fovDeg * DEG) / 2), elevationDeg * DEG] },
        uStacked: { value: stacked ? 1 : 0 },
        uSunDir: { value: directionFromAngles(35, 40) },
        uN: { value: COAT_INDEX },
        uKd: { value: KD },
        uMetalN: { value: metal?.n ?? [1, 1, 1] },
        uMetalK: { value: metal?.k ?? [0, 0, 0] },
      });
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.viewport(0, 0, width, height);
      program.draw();
      target.width = width;
      target.height = height;
      target.getContext('2d').drawImage(canvas, 0, 0); // in the same task, before the buffer is cleared
    },
    dispose() {
      program?.dispose();
      program = null;
    },
  };
}
