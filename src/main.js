// @ts-check
// The lecture page: one section per panel of the manifest, in lecture order (vite.config.js
// writes them into index.html), each mounted as it approaches the screen; the page controls and
// lecture-mode keys. A composed lecture (?lecture=CODE, or a data element in the page) takes the
// place of those sections with its own items (src/lecture/mountLecture.js), with all of the rest.
import './styles.css';
import './panelPlaces.css';
import { PANEL_IDS, lecturePrefix, panelEntry } from './panels/manifest.js';
import { missingFiles, panelDefinition } from './panels/loadPanel.js';
import { createPanelHost } from './host/createPanelHost.js';
import { managePanels } from './host/managePanels.js';
import { setupLectureMode } from './host/setupLectureMode.js';
import { setupPageControls } from './host/setupPageControls.js';
import { showNotice } from './host/showNotice.js';
import { installPageFaults } from './host/panelFaults.js';
import { contextStats, MAX_LIVE_CONTEXTS } from './gl/contextBudget.js';
import { describeProblem, readParams, withDefaults } from './host/params.js';
import { itemLectureUrl } from './host/shareLinks.js';
import { texReady } from './ui/tex.js';
import { LECTURE_ELEMENT_ID } from './lecture/lectureElement.js';
import { audioTraceOn, installAudioKey, onAudioTrace, setAudioTrace, traceLog } from './ui/createAudioTrace.js';
import { panelTitle } from './panels/panelText.js';
import { startPageLanguage } from './i18n/pageLanguage.js';
import { messages } from './i18n/messages.js';
import { pageElement } from './ui/pageElement.js';

// The page's language first: every word below is written in it. A composed lecture carries its own
// (the "lang" of its link's code, or of the data element of an offline lecture), which the link's
// ?lang= still beats, as a homework sheet's does.
const language = await startPageLanguage({ carried: await carriedLectureLanguage() });

/**
 * The language of the lecture the page shows, given by ?lecture= or written into the page
 * (offline/index.html), the link first as openLecture.js takes it; read without reading the rest
 * (the code's decoder comes only with a lecture link).
 */
async function carriedLectureLanguage() {
  const code = new URLSearchParams(window.location.search).get('lecture');
  if (code !== null) {
    // A decoder that cannot load leaves the choice to the rest (the lecture's own loading says why).
    return import('./lecture/lectureCode.js').then(({ lectureCodeLanguage }) => lectureCodeLanguage(code), () => null);
  }
  const data = document.getElementById(LECTURE_ELEMENT_ID);
  if (!(data instanceof HTMLScriptElement) || data.type !== 'application/json') return null;
  try {
    const lang = JSON.parse(data.textContent ?? '')?.lang;
    return typeof lang === 'string' ? lang : null;
  } catch {
    return null;
  }
}

/**
 * A notice titled in the page's own words (the catalogue's "page" namespace). Only a problem shows
 * one, so those words are fetched then: the first load carries none of them. lines: the notice's
 * lines, or a function of t that makes them in those words.
 * @param {HTMLElement} host
 * @param {string} key
 * @param {string[] | ((t: (key: string, args?: Record<string, unknown>) => string) => string[])} lines
 * @param {{ args?: Record<string, unknown>, kind?: 'warning' | 'error' }} [options]
 */
async function pageNotice(host, key, lines, { args, kind } = {}) {
  const { default: english } = await import('virtual:messages/en/page');
  const t = messages('page', english);
  return showNotice(host, t(key, args), typeof lines === 'function' ? lines(t) : lines, { kind });
}

/** @type {Record<string, import('./host/createPanelHost.js').PanelHost>} */
const hosts = {};
/**
 * @type {{ hosts: typeof hosts, contexts: typeof contextStats, panels: object, audio: object, ready: Promise<void> | null,
 *   applyMaterial?: typeof applyMaterial, lecture?: { source: string, title: string | null, code: string | null } }}
 */
const lab = {
  hosts,
  contexts: contextStats,
  /** Each mounted panel's view (null while it is away), for scripts and tests. */
  panels: new Proxy({}, { get: (_t, id) => (typeof id === 'string' && Object.hasOwn(hosts, id) ? hosts[id].instance : null) }),
  /** The audio trace: on or off, and every sound it made (createAudioTrace.js). */
  audio: { get on() { return audioTraceOn(); }, log: traceLog },
  ready: null,
};
window.fresnelLab = lab;

/**
 * Page-wide material: every panel that has an index parameter takes it (a table marks its row).
 * @param {{ id?: string, n: number }} material
 */
function applyMaterial(material) {
  for (const host of Object.values(hosts)) {
    const { material: key, materialSelect } = host.panel;
    if (key) host.set({ [key]: material.n }, { source: 'page' });
    else if (materialSelect && material.id) host.set({ [materialSelect]: material.id }, { source: 'page' });
  }
}

const controls = setupPageControls(pageElement('.page-controls'), { onMaterial: applyMaterial });
lab.applyMaterial = applyMaterial;

// ?maxContexts=N holds fewer WebGL panels at once, for a weak laptop (at most 8, the default).
/** @satisfies {import('./host/panelContract.js').Schema} */
const pageSchema = {
  maxContexts: { type: 'number', default: MAX_LIVE_CONTEXTS, min: 1, max: MAX_LIVE_CONTEXTS, step: 1 },
  audio: { type: 'boolean', default: false },
};
const page = readParams(pageSchema, new URLSearchParams(window.location.search));
const main = pageElement('main');
// An error nobody caught is said in its panel, or once at the top of the page (panelFaults.js).
installPageFaults((title, lines) => showNotice(main, title, lines, { kind: 'error' }));
if (page.problems.length) pageNotice(main, 'settingsProblem', page.problems.map(describeProblem));
if (language.problem) pageNotice(main, 'languageProblem', [language.problem]);
const maxLive = Math.round(page.values.maxContexts);
// The audio trace (A, or the button under a plot) is kept in the link, so a shared link keeps it.
setAudioTrace(page.values.audio, 'url');
installAudioKey();
onAudioTrace((on) => {
  const url = new URL(window.location.href);
  if (on) url.searchParams.set('audio', '1');
  else url.searchParams.delete('audio');
  window.history.replaceState(window.history.state, '', url);
});

// A composed lecture, from the link or the page; what it holds that cannot be used is named, and
// the rest opens. One that cannot be read at all is named, and the lab's own lecture is shown. Its
// code (reading, Markdown, KaTeX) comes only with a lecture: the lab's own needs none of it.
const search = new URLSearchParams(window.location.search);
const element = document.getElementById(LECTURE_ELEMENT_ID);
const carried = element instanceof HTMLScriptElement && element.type === 'application/json' ? element.textContent : null;
const given = search.has('lecture') || carried !== null
  ? import('./lecture/composedLecture.js').then(({ showComposedLecture }) => showComposedLecture(main, search, carried))
  : null;
// Until it is read, the lab's own sections wait unseen: a lecture given does not flash the default one first.
if (given) main.classList.add('lecture-pending');
// The composer runs from the site (it reads the offline page beside it): a page opened from disk has none beside it.
if (window.location.protocol === 'file:') document.querySelector('.compose-offer')?.remove();

/** The lab's own lecture: its panels, each in the section the build wrote for it. */
function ownPanels() {
  // The page and the manifest must agree: a section without a panel, or a panel without its section
  // or its module, is said on the page (and fails the tests), never dropped in silence.
  const sections = [...document.querySelectorAll('section[data-panel]')].filter((s) => s instanceof HTMLElement);
  const onPage = sections.map((s) => s.dataset.panel ?? '');
  const strays = onPage.filter((id) => !panelEntry(id));
  const unplaced = PANEL_IDS.filter((id) => !onPage.includes(id));
  if (strays.length || unplaced.length || missingFiles.length) {
    pageNotice(main, 'manifestProblem', (t) => [...strays.map((id) => t('sectionWithoutPanel', { id })),
      ...unplaced.map((id) => t('panelWithoutSection', { id })), ...missingFiles], { kind: 'error' });
  }
  const panels = sections.map((section) => {
    const id = section.dataset.panel ?? '';
    return { section, key: id, item: null, prefix: lecturePrefix(id) };
  });
  return { sections, panels };
}

/**
 * A panel item's host options: it starts from the item's state, its link keeps the lecture (its
 * code, or this page where the page holds it) with this item's state, and its embed code the
 * item's locks and hidden controls.
 * @param {{ item: import('./lecture/readLecture.js').PanelItem | null, key: string, prefix: string }} placed
 * @param {import('./host/panelContract.js').Schema} schema
 * @param {Awaited<ReturnType<typeof import('./lecture/composedLecture.js').showComposedLecture>> | null} opened
 */
function itemOptions({ item, key, prefix }, schema, opened) {
  if (!item || !opened) return {}; // an item comes with an opened lecture
  const start = item.state ?? {};
  const page = opened.source === 'data' ? window.location.href : './index.html';
  const code = opened.source === 'data' ? null : opened.code;
  const lang = code ? search.get('lang') : null; // a lecture link's language goes with it
  return {
    start,
    lectureLink: (/** @type {Readonly<import('./host/panelContract.js').Values>} */ values) =>
      itemLectureUrl({ page, code, lang, schema: withDefaults(schema, start), prefix, key }, values),
    embedOptions: { lock: item.lock ?? [], hide: item.hide ?? [] },
  };
}

// Every panel's host (values, link, messages) at once; each panel's module when it comes near.
lab.ready = (async () => {
  const opened = given ? await given.catch((error) => {
    pageNotice(main, 'lectureLoadFailed', [error.message], { kind: 'error' });
    return null;
  }) : null;
  lab.lecture = { source: opened?.source ?? 'default', title: opened?.title ?? null, code: opened?.code ?? null };
  const composeLink = document.querySelector('.compose-offer a');
  // The composer opens it in this page's language (the lecture's own, unless the reader chose another).
  if (composeLink instanceof HTMLAnchorElement && opened?.code) {
    composeLink.href = `./compose.html?lecture=${opened.code}&lang=${encodeURIComponent(language.id)}`;
  }
  const composed = opened?.composed ?? null;
  main.classList.remove('lecture-pending');
  const { sections, panels } = composed ?? ownPanels();
  const entries = panels.map((placed) => {
    const { section, key } = placed;
    const id = section.dataset.panel ?? '';
    try {
      const definition = panelDefinition(id);
      hosts[key] = createPanelHost(pageElement('.panel-mount', section), definition, {
        prefix: placed.prefix, noticeHost: section, applyMaterial, ...itemOptions(placed, definition.schema, opened),
      });
      if (placed.item?.lock) hosts[key].controls('lock', placed.item.lock);
      if (placed.item?.hide) hosts[key].controls('hide', placed.item.hide);
      return { section, host: hosts[key] };
    } catch (error) {
      const said = error instanceof Error ? error.message : String(error);
      pageNotice(section, 'panelLoadFailed', [said], { kind: 'error', args: { title: panelEntry(id) ? panelTitle(id) : id } });
      return null;
    }
  });
  const lecture = setupLectureMode(sections, { onHideControls: controls.toggleControls });
  const hosted = entries.filter((entry) => entry !== null);
  const manager = managePanels(hosted, { maxLive });
  lecture.holdHashTarget(manager.first);
  await manager.first; // the panels on screen are mounted
  // Once the first picture is up, the other panels' modules are fetched (small chunks, in
  // parallel), so a panel scrolled or keyed to mounts at once, at full size, moving nothing.
  // `ready` means all of it: the page behaves from then on as if everything were here.
  await new Promise((resolve) => { requestAnimationFrame(() => setTimeout(resolve, 0)); });
  // KaTeX too: the page's formulas are typeset as their panels mount, not after (which would
  // change their height under the reader).
  // A failure is shown in its panel (a question's, in its section).
  await Promise.allSettled([texReady(), composed?.ready, ...hosted.map((e) => e.host.load())]);
})();
