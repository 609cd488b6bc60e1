// @ts-check
// embed.html?panel=ID&<params>&<embed options>: one panel alone, no page chrome, sized to its
// frame, driven by its URL and by the message API (src/host/messageApi.js). The embed options
// (readEmbedOptions.js) set the theme, projector mode, reduced motion, locked or hidden controls
// and the deck's origin.
import './styles.css';
import { PANEL_IDS, panelEntry } from './panels/manifest.js';
import { loadPanel } from './panels/loadPanel.js';
import { createPanelHost } from './host/createPanelHost.js';
import { connectMessages, parseMessage } from './host/messageApi.js';
import { readEmbedOptions } from './host/readEmbedOptions.js';
import { startPageLanguage } from './i18n/pageLanguage.js';
import { matchLanguage } from './i18n/languages.js';
import { currentLanguage } from './i18n/messages.js';
import { describeProblem, writeParams } from './host/params.js';
import { applyTheme, loadTheme } from './ui/theme.js';
import { setSubscripted } from './ui/subscripts.js';
import { showNotice } from './host/showNotice.js';
import { installPageFaults } from './host/panelFaults.js';
import { contextStats } from './gl/contextBudget.js';
import { audioTraceOn, installAudioKey, onAudioTrace, setAudioTrace, traceLog } from './ui/createAudioTrace.js';
import { panelTitle } from './panels/panelText.js';
import { labTitle } from './host/shareLinks.js';
import english from 'virtual:messages/en/embed';
import { messages } from './i18n/messages.js';
import { pageElement } from './ui/pageElement.js';

const t = messages('embed', english);

// The language first (?lang=, a deck's option, read by language.js from the link): every word below is in it.
const language = await startPageLanguage();
const root = pageElement('#embed');
installPageFaults((title, lines) => showNotice(root, title, lines, { kind: 'error' }));
const search = new URLSearchParams(window.location.search);
const id = search.get('panel');
/** @typedef {import('./host/createPanelHost.js').PanelHost} PanelHost */
/** @type {Record<string, PanelHost>} */
const hosts = {};
/**
 * The page's hook for the browser tests and decks' scripts.
 * @type {{ hosts: typeof hosts, contexts: typeof contextStats, panels: object, ready: Promise<PanelHost | null> | null, audio: object,
 *   fit: ReturnType<typeof import('./host/fitToFrame.js').fitToFrame> | null }}
 */
const lab = {
  hosts,
  contexts: contextStats,
  panels: new Proxy({}, { get: (_t, key) => (typeof key === 'string' && Object.hasOwn(hosts, key) ? hosts[key].instance : null) }),
  ready: null,
  fit: null, // with fit=1, the layout fitted to the frame (fitToFrame.js), once that module is here
  audio: { get on() { return audioTraceOn(); }, log: traceLog },
};
window.fresnelLab = lab;
const { options, problems } = readEmbedOptions(search);
// Said at once, before the panel's module arrives: a page that frames this one learns that its frame
// holds the lab's embed page, not the browser's error page (src/ui/watchPanelFrame.js).
if (window.parent !== window && options.parentOrigin !== 'none') {
  window.parent.postMessage({ type: 'fresnel-lab:loading', panel: id }, options.parentOrigin ?? '*');
}
// What the reader's browser remembers, overridden by the embed's URL and then by messages; never
// stored, since it is the deck's choice, not the reader's.
const theme = { ...loadTheme() };
if (options.theme) theme.scheme = options.theme;
if (options.projector !== null) theme.projector = options.projector;
applyTheme(theme, { remember: false });
showNotice(root, t('optionsProblem'), problems.map(describeProblem));
if (language.problem) showNotice(root, t('languageProblem'), [language.problem]);
setAudioTrace(options.audio, 'url');
installAudioKey();

// A deck may leave the slide before the panel's module is here (reveal.js posts 'slide:stop' to
// the frames of the slide it leaves): remember it, and do not start drawing until it resumes.
let stoppedEarly = false;
const early = (/** @type {MessageEvent} */ event) => {
  const { parentOrigin } = options;
  if (parentOrigin === 'none' || (parentOrigin && event.origin !== parentOrigin)) return;
  const kind = parseMessage(event.data)?.kind;
  if (kind === 'pause') stoppedEarly = true;
  else if (kind === 'resume') stoppedEarly = false;
};
window.addEventListener('message', early);

/**
 * The embed again in `lang` (a deck's message), as it is now: its values and its locked and hidden
 * controls written into its link (the link's own copy of the values follows changes a moment late).
 * @param {string} lang
 * @param {PanelHost} host
 */
function restartIn(lang, host) {
  const id = matchLanguage(lang);
  if (!id || id === currentLanguage()) return;
  const url = new URL(window.location.href);
  writeParams(host.panel.schema, host.values, url.searchParams);
  for (const [key, keys] of Object.entries({ lock: host.locked, hide: host.hiddenControls })) {
    if (keys.length) url.searchParams.set(key, keys.join(','));
    else url.searchParams.delete(key);
  }
  url.searchParams.set('lang', id);
  window.location.replace(url.toString());
}

lab.ready = (async () => {
  const entry = id ? panelEntry(id) : undefined;
  if (!entry) {
    showNotice(root, id ? t('noSuchPanel', { id }) : t('noPanel'), [t('panelIds', { ids: PANEL_IDS.join(', ') })], { kind: 'error' });
    return null;
  }
  document.title = labTitle(entry.id);
  const heading = document.createElement('h1');
  heading.className = 'embed-title';
  setSubscripted(heading, panelTitle(entry.id)); // n_t with a real subscript, as the lecture page's heading
  root.append(heading);
  let panel;
  try {
    panel = await loadPanel(entry.id);
  } catch (error) {
    showNotice(root, t('panelLoadFailed', { title: panelTitle(entry.id) }), [error instanceof Error ? error.message : String(error)],
      { kind: 'error' });
    return null;
  }
  /** @type {ReturnType<typeof connectMessages> | null} */
  let messages = null;
  const host = createPanelHost(root, panel, {
    titleLevel: 1, // the embed's title is its h1
    applyMaterial: (material) => panel.material && host.set({ [panel.material]: material.n }, { source: 'page' }),
    onFrame: (frame) => messages?.rendered(frame),
  });
  hosts[entry.id] = host;
  if (options.reducedMotion !== null) host.setReducedMotion(options.reducedMotion);
  const unknown = [...host.controls('lock', options.lock), ...host.controls('hide', options.hide)];
  if (!options.controls) host.controls('hide', null);
  // Only a slide's frame asks to be fitted: the layout search comes with fit=1, not with every embed.
  if (options.fit) {
    import('./host/fitToFrame.js').then(({ fitToFrame }) => { lab.fit = fitToFrame(root, { moreBelow: t('fitMoreBelow') }); });
  }
  showNotice(root, t('controlsProblem'), unknown.map((k) => t('notAControl', { key: k })));
  // The view is shown while the deck has not paused it and the frame is on screen. Paused (a
  // deck's hidden slide) or off screen for a second (a slide reveal.js preloaded ahead, a page
  // scrolled past), it is disposed, which frees its WebGL context; the values stay with the host,
  // so it comes back exactly as it was.
  let paused = stoppedEarly;
  let onScreen = true;
  const show = () => {
    const wanted = !paused && onScreen;
    if (wanted && !host.mounted) host.mount();
    else if (!wanted && host.mounted) host.unmount();
  };
  let leaving = 0;
  if (typeof IntersectionObserver === 'function') new IntersectionObserver((entries) => {
    clearTimeout(leaving);
    if (entries.at(-1)?.isIntersecting) {
      onScreen = true;
      show();
    } else {
      leaving = setTimeout(() => { onScreen = false; show(); }, 1000);
    }
  }).observe(document.documentElement);
  messages = connectMessages(host, {
    origin: options.parentOrigin ?? '*',
    page: {
      theme: (scheme) => applyTheme(Object.assign(theme, { scheme }), { remember: false }),
      projector: (on) => applyTheme(Object.assign(theme, { projector: on }), { remember: false }),
      reducedMotion: (on) => host.setReducedMotion(on),
      audio: (on) => setAudioTrace(on, 'api'),
      language: (lang) => restartIn(lang, host),
      pause() { paused = true; show(); },
      resume() { paused = false; show(); },
    },
  });
  window.removeEventListener('message', early);
  onAudioTrace((on, source) => { if (source !== 'api') messages?.audio(on); }); // the reader's switch, told to the deck
  show();
  messages.ready();
  // The content's height, whenever it changes (a panel mounting, projector mode, a notice), so a
  // host page can size the frame to fit: the homework sheet does, and so can an LMS page.
  let lastHeight = 0;
  if (typeof ResizeObserver === 'function') new ResizeObserver(() => {
    const height = Math.ceil(document.body.scrollHeight);
    if (height !== lastHeight) messages?.size((lastHeight = height));
  }).observe(document.body);
  return host;
})();
