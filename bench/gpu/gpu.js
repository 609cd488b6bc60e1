// The real-GPU check (README.md beside it): built with the benchmark's peer page
// (FRESNEL_LAB_BENCH_PEER=1) and opened in a headless Chromium on the GPU machine. It runs the
// speed-accuracy panel's benchmark (every method's cost and error, and the hero's frame costs), the
// normal-map viewer's chain build, and the hero embed against the two three.js peers driven by the
// same messages, and logs each result as `GPUH <tag> <chunk> <json>` console lines (long JSON in
// chunks, since the shell's log cuts long lines), then `GPUH DONE`. ?size=tiny is a quick run;
// ?steps=probe,hero runs only those steps.
const query = new URLSearchParams(window.location.search);
const size = query.get('size') === 'tiny' ? 'tiny' : 'normal';
const only = (query.get('steps') ?? '').split(',').filter(Boolean);
const ROOT = new URL('../../', window.location.href); // the site's root: this page is bench/gpu/gpu.html
const CHUNK = 6000;

function log(tag, value) {
  const text = JSON.stringify(value);
  for (let i = 0, k = 0; i < text.length; i += CHUNK, k += 1) console.log(`GPUH ${tag} ${k} ${text.slice(i, i + CHUNK)}`);
  console.log(`GPUH ${tag} end`);
}

const sleep = (ms) => new Promise((resolve) => { setTimeout(resolve, ms); });
function within(promise, ms, what) {
  return Promise.race([promise, sleep(ms).then(() => { throw new Error(`${what}: no answer within ${ms / 1000} s`); })]);
}

/** One page of the site in a frame of its own, width × height. */
function frame(path, width, height) {
  document.body.replaceChildren();
  const element = document.createElement('iframe');
  element.style.cssText = `width:${width}px;height:${height}px;border:0;display:block`;
  element.src = new URL(path, ROOT).href;
  document.body.append(element);
  return element;
}

/** The frame's window.fresnelLab once it is ready. */
async function lab(element, ms = 120_000) {
  const end = performance.now() + ms;
  while (performance.now() < end) {
    const found = element.contentWindow?.fresnelLab;
    if (found?.ready) {
      await found.ready;
      return found;
    }
    await sleep(50);
  }
  throw new Error(`no window.fresnelLab in ${element.src}`);
}

function probe() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return { webgl2: false };
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return {
    webgl2: true,
    renderer: info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
    vendor: info ? gl.getParameter(info.UNMASKED_VENDOR_WEBGL) : gl.getParameter(gl.VENDOR),
    timer: Boolean(gl.getExtension('EXT_disjoint_timer_query_webgl2')),
    floatTargets: Boolean(gl.getExtension('EXT_color_buffer_float')),
    highpFrag: gl.getShaderPrecisionFormat(gl.FRAGMENT_SHADER, gl.HIGH_FLOAT).precision,
    mediumpFrag: gl.getShaderPrecisionFormat(gl.FRAGMENT_SHADER, gl.MEDIUM_FLOAT).precision,
    language: navigator.language,
  };
}

async function speedAccuracy() {
  const element = frame(`embed.html?panel=speed-accuracy&bench=${size}`, 1280, 900);
  const panel = (await lab(element)).panels['speed-accuracy'];
  const started = performance.now();
  const finished = await within(panel.autorun, 600_000, 'the speed-accuracy benchmark');
  log('sa-meta', { finished: Boolean(finished), seconds: (performance.now() - started) / 1000 });
  if (finished) {
    log('sa-table', panel.resultsTable());
    log('sa-json', panel.resultsJson());
  }
}

async function normalMips() {
  const element = frame('embed.html?panel=normal-mips&truth=false', 1280, 900);
  const found = await lab(element);
  const n = size === 'tiny' ? 64 : 1024;
  log('nm', await within(found.panels['normal-mips'].bench({ size: n, repeats: n > 256 ? 5 : 3 }), 300_000, 'the chain build'));
}

/** ms per message-driven update of the page at `path` (set → rendered), as bench/measurePages.js. */
async function updates(path, count) {
  const element = frame(path, 1500, 600);
  const next = (type) => new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no ${type} from ${path}`)), 60_000);
    const on = (event) => {
      if (event.source !== element.contentWindow || event.data?.type !== type) return;
      window.removeEventListener('message', on);
      clearTimeout(timer);
      resolve(event.data);
    };
    window.addEventListener('message', on);
  });
  await next('fresnel-lab:ready');
  const samples = [];
  for (let i = 0; i < count + 4; i += 1) {
    const rendered = next('fresnel-lab:rendered');
    const t0 = performance.now();
    element.contentWindow.postMessage({ type: 'fresnel-lab:set', params: { nT: 1.3 + (i % 10) * 0.05 } }, '*');
    await rendered;
    if (i >= 4) samples.push(performance.now() - t0); // four to warm up
  }
  samples.sort((a, b) => a - b);
  return { median: samples[samples.length >> 1], min: samples[0], max: samples[samples.length - 1] };
}

async function hero() {
  const count = size === 'tiny' ? 6 : 32;
  const rounds = [];
  for (let r = 0; r < (size === 'tiny' ? 1 : 5); r += 1) {
    rounds.push({
      hero: await updates('embed.html?panel=spheres', count),
      peer: await updates('bench/peer.html', count),
      plainPeer: await updates('bench/peer.html?clearcoat=0', count),
    });
  }
  log('hero', rounds);
}

const STEPS = { probe: async () => log('probe', probe()), 'speed-accuracy': speedAccuracy, 'normal-mips': normalMips, hero };
for (const [name, step] of Object.entries(STEPS)) {
  if (only.length && !only.includes(name)) continue;
  const started = performance.now();
  try {
    await step();
  } catch (error) {
    log('error', { step: name, message: String(error?.message ?? error) });
  }
  log('step', { name, seconds: (performance.now() - started) / 1000 });
}
console.log('GPUH DONE');
