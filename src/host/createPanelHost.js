// @ts-check
// The frame around every panel. The host owns the panel's values: it reads them from the URL,
// validates every write against the schema (from a control, the panel itself, a message or the
// page), says on screen what it rejected, and passes each change on to the controls, the URL, the
// panel's picture, its description and any listener (the message API); the values, their checks
// and that order are the store's (createValueStore.js), the rest is this frame's DOM. It also
// holds the toolbar (createToolbar.js) and mounts and disposes the panel's view. Values outlive
// the view, so a panel disposed to free its WebGL context comes back exactly as it was.
import { warmGpu } from '../gl/warmGpu.js';
import { ownedBy } from '../gl/faultOwner.js';
import { createPanelFaults, watchInputs } from './panelFaults.js';
import { defaults, describeProblem, withDefaults } from './params.js';
import { createControlState } from './createControlState.js';
import { bindGui, createPanelGui } from './bindGui.js';
import { readUrlState, urlWriter } from './urlState.js';
import { showNotice } from './showNotice.js';
import { resizePng, toCsv } from './exporters.js';
import { embedCode, embedUrl, labTitle, lectureUrl } from './shareLinks.js';
import { createToolbar } from './createToolbar.js';
import { checkInstance } from './panelContract.js';
import { createValueStore } from './createValueStore.js';
import { el } from '../ui/el.js';
import { cssVar } from '../ui/theme.js';
import { panelTitle } from '../panels/panelText.js';
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';

const t = messages('host', english);
let nextDescriptionId = 0;

/** @typedef {import('./panelContract.js').PanelInstance} PanelInstance */
/** @typedef {import('./panelContract.js').Values} Values */
/** @typedef {NonNullable<import('./panelContract.js').PanelDefinition['mount']>} MountPanel */
/** @typedef {ReturnType<typeof createPanelHost>} PanelHost */

/** What was thrown, in words. @param {unknown} error */
const messageOf = (error) => (error instanceof Error ? error.message : String(error));

/**
 * container: where the panel lives (a section's .panel-mount, or the embed root).
 * panel: its definition (manifest entry, schema, mount; see panelContract.js).
 * prefix: URL key prefix ('' for the hero and embeds, 'id.' for other lecture-page panels).
 * titleLevel: the level of the panel's title heading (2 on the lecture page, 1 in an embed); a
 * panel's own headings are h3, one level below 2, and are said one level below the title.
 * @param {HTMLElement} container
 * @param {import('./panelContract.js').PanelDefinition} panel
 * start: where the panel starts when the link says nothing (a composed lecture's item; else its defaults);
 * lectureLink(values): the Copy link's address (else the lecture page's); embedOptions: lock and hide for the embed code.
 * @param {{ prefix?: string, noticeHost?: HTMLElement, onFrame?: (frame: number) => void, titleLevel?: number,
 *   applyMaterial?: (material: { id?: string, name?: string, n: number }) => void, start?: Readonly<Values>,
 *   lectureLink?: (values: Readonly<Values>) => string, embedOptions?: { lock?: readonly string[], hide?: readonly string[] } }} [options]
 */
export function createPanelHost(container, panel, {
  prefix = '', noticeHost = container, onFrame = () => {}, applyMaterial = () => {}, titleLevel = 2,
  start: itemStart = {}, lectureLink = (v) => lectureUrl(panel, v), embedOptions = {},
} = {}) {
  const { schema } = panel;
  const urlSchema = withDefaults(schema, itemStart); // the link says what differs from where the panel starts
  const { values: start, problems } = readUrlState(urlSchema, prefix); // what the link asked for: `reset` returns here
  showNotice(noticeHost, t('linkValuesTitle'), problems.map(describeProblem));
  const writeUrl = urlWriter(urlSchema, prefix);
  const draft = { ...start }; // what the controls edit; the host writes it back after each change

  const shell = el('div', 'panel-shell');
  const content = el('div', 'panel-content');
  const side = el('div', 'panel-side');
  const guiHost = el('div', 'gui-host');
  const tools = createToolbar(panel.id, {
    link: () => lectureLink(values),
    embed: () => embedCode(panel, values, embedOptions),
    png: () => instance?.png?.(),
    poster: () => poster(),
    csv: () => instance?.csv?.(),
  });
  const toolbar = tools.element;
  const description = el('p', 'panel-description');
  description.id = `panel-description-${(nextDescriptionId += 1)}`;
  side.append(guiHost, toolbar);
  // Shown from the mount on, below the controls: were it shown before, the controls arriving above
  // it would move it (a layout shift on the lecture page).
  toolbar.hidden = true;
  shell.append(content, side);
  container.append(shell, description);
  // Faults once the panel runs (an error in its code, a lost context) are said on this line.
  const faults = createPanelFaults({ title: panelTitle(panel.id), restart: () => restart() });
  shell.before(faults.element);
  watchInputs(container, faults);
  /**
   * Runs the panel's own code: what it makes is the panel's, and what it throws is said in the panel.
   * @template T
   * @param {() => T} fn
   * @returns {T | undefined}
   */
  const guarded = (fn) => {
    try {
      return ownedBy(faults, fn);
    } catch (error) {
      faults.fail(error);
      return undefined;
    }
  };
  const controlState = createControlState(schema, shell);
  const prefersReducedMotion = window.matchMedia?.('(prefers-reduced-motion: reduce)').matches ?? false;
  /** @type {boolean | null} */
  let reducedMotion = null; // set by the embed's URL or a message; null: the reader's preference

  /** @type {PanelInstance | null} */
  let instance = null;
  /** @type {import('lil-gui').default | null} */
  let gui = null;
  /** @type {Record<string, import('lil-gui').Controller>} */
  let controllers = Object.create(null); // keyed by schema keys only: a name from outside finds nothing inherited
  let frames = 0;
  /** @type {HTMLElement | null} */
  let rejectedNotice = null;
  /** @type {MountPanel | null} */
  let mountPanel = panel.mount ?? null; // or, until panel.load() resolves, null
  /** @type {Promise<void> | null} */
  let loading = null;
  let wanted = false;
  let startFailed = false; // mount() threw: not tried again by itself (the notice says so)

  // The values (createValueStore.js): a change reaches the controls, the picture, the description,
  // the URL and then the listeners (the message API).
  const store = createValueStore(panel.id, schema, start, {
    isLocked: (key) => controlState.isLocked(key),
    show(keys) {
      for (const key of keys) {
        draft[key] = values[key];
        controllers[key]?.updateDisplay();
      }
    },
    refused(rejected) {
      rejectedNotice?.remove();
      rejectedNotice = showNotice(noticeHost, t('panelValuesTitle', { title: panelTitle(panel.id) }), rejected.map(describeProblem));
    },
    redraw: (keys) => guarded(() => instance?.update(keys)),
    settled() {
      refreshDescription();
      domFrameDrawn();
      writeUrl(values);
    },
  });
  const { values, set } = store;

  /** A frame of the panel's picture is drawn: counted, marked once for timing, and announced. */
  function frameDrawn() {
    frames += 1;
    if (frames === 1) performance.mark?.(`fresnel-lab:first-frame:${panel.id}`);
    onFrame(frames);
  }
  // A panel without WebGL draws its picture (plots, tables, formulas) during update; its frame is
  // the next animation frame, when the browser shows it (uPlot commits in a microtask before that).
  let domFrame = 0;
  const domFrameDrawn = () => {
    if (panel.webgl || domFrame) return;
    domFrame = requestAnimationFrame(() => {
      domFrame = 0;
      if (instance) frameDrawn();
    });
  };

  /** The slide-sized poster of this view (makePoster.js): its picture, or its largest canvas (a plot). */
  async function poster() {
    if (!instance) return null;
    const canvases = [...content.querySelectorAll('canvas')].sort((a, b) => b.width * b.height - a.width * a.height);
    const picture = instance.png?.() ?? canvases[0]?.toDataURL('image/png') ?? null;
    const { makePoster } = await import('./makePoster.js');
    return makePoster({
      picture,
      title: `${labTitle(panel.id).replace(/_([it])\b/g, (_, /** @type {'i' | 't'} */ c) => ({ i: 'ᵢ', t: 'ₜ' })[c])}`,
      link: lectureLink(values),
      colours: { background: cssVar('--bg', '#0d1117'), text: cssVar('--text', '#f0f3f6'), muted: cssVar('--muted', '#c2cad3') },
    });
  }

  function refreshDescription() {
    const shown = instance;
    description.textContent = (shown && guarded(() => shown.describe())) ?? '';
    for (const canvas of content.querySelectorAll('canvas')) canvas.setAttribute('aria-describedby', description.id);
  }

  /** Loads the panel's module once; a failure is shown in the panel and rejects. */
  function load() {
    if (mountPanel) return Promise.resolve();
    const module = panel.load?.() ?? Promise.reject(new Error(`The ${panel.id} panel has neither mount() nor load().`));
    // A WebGL panel also waits for the GPU channel to open off the page's thread (warmGpu.js).
    loading ??= Promise.all([module, panel.webgl ? warmGpu() : null]).then(([fn]) => { mountPanel = fn; }, (error) => {
      showNotice(noticeHost, t('panelLoadFailed', { title: panelTitle(panel.id) }), [messageOf(error)], { kind: 'error' });
      throw error;
    });
    return loading;
  }

  /** @param {MountPanel} start the panel's mount() */
  function mountNow(start) {
    wanted = true;
    container.style.minHeight = '';
    const root = createPanelGui(guiHost, t('controlsTitle', { title: panelTitle(panel.id) }));
    gui = root;
    toolbar.hidden = false;
    controllers = Object.create(null);
    controlState.clear();
    try {
      // Values set during mount (code kept in this browser) are where the panel starts, not a change.
      instance = checkInstance(panel.id, store.quietly(() => ownedBy(faults, () => start(content, ctx))));
    } catch (error) {
      instance = null;
      startFailed = true;
      root.destroy();
      gui = null;
      toolbar.hidden = true;
      content.replaceChildren();
      showNotice(noticeHost, t('panelStartFailed', { title: panelTitle(panel.id) }), [messageOf(error), t('panelStartAgain')],
        { kind: 'error' });
      throw error;
    }
    const made = instance;
    tools.offer(made);
    if (titleLevel !== 2) for (const heading of content.querySelectorAll('h3')) heading.setAttribute('aria-level', String(titleLevel + 1));
    refreshDescription();
    domFrameDrawn();
    return made;
  }

  /**
   * Shows the panel: its instance, or (while its module loads) a promise of it, which resolves
   * to null when the panel was unmounted meanwhile. A failure is shown in the panel and thrown;
   * a panel that failed to start is not started again (null).
   */
  function mount() {
    if (instance) return instance;
    if (startFailed) return null;
    if (mountPanel) return mountNow(mountPanel);
    wanted = true;
    return load().then(() => (wanted && !instance && !startFailed && mountPanel ? mountNow(mountPanel) : instance));
  }

  function unmount() {
    wanted = false;
    if (!instance) return;
    // No layout jump while it is away; rounded down, so the place is never taller than the panel was.
    container.style.minHeight = `${Math.floor(container.getBoundingClientRect().height)}px`;
    cancelAnimationFrame(domFrame);
    domFrame = 0;
    const gone = instance;
    instance = null;
    guarded(() => gone.dispose());
    faults.reset();
    gui?.destroy();
    gui = null;
    toolbar.hidden = true;
    controllers = Object.create(null);
    controlState.clear();
    content.replaceChildren();
  }

  /** After an error: the panel is disposed and mounted again, with its values. */
  function restart() {
    unmount();
    container.style.minHeight = '';
    const again = mount();
    if (again instanceof Promise) again.catch(() => {}); // a failure is said in the panel
  }

  // The GUI is made before the panel's mount() runs, and lives as long as the panel is mounted.
  const mountedGui = () => {
    if (!gui) throw new Error(`The ${panel.id} panel asked for its controls while not mounted.`);
    return gui;
  };

  /** @type {import('./panelContract.js').PanelContext} */
  const ctx = {
    values,
    get gui() { return mountedGui(); },
    bind(folder, keys) {
      const onChange = (/** @type {string} */ key, /** @type {unknown} */ value) => set({ [key]: value }, { source: 'user' });
      const made = bindGui(folder ?? mountedGui(), panel.id, schema, draft, onChange, keys);
      Object.assign(controllers, made);
      controlState.bind(controllers);
      return made;
    },
    set: (update, options) => set(update, { source: 'user', ...options }),
    tie: (controller, keys) => controlState.tie(controller, keys),
    invalidate() {
      guarded(() => instance?.update([]));
      refreshDescription();
      domFrameDrawn();
    },
    frameDrawn,
    applyMaterial: (material) => applyMaterial(material),
    // The reader's own preference always holds; an embed may ask for less motion, never for more.
    get reducedMotion() { return prefersReducedMotion || reducedMotion === true; },
  };

  return {
    id: panel.id,
    panel,
    container,
    values,
    usesWebGL: panel.webgl,
    get mounted() { return instance !== null; },
    get instance() { return instance; },
    get frames() { return frames; },
    /** Errors met since start, and contexts lost now (panelFaults.js). */
    get faults() { return { errors: faults.count, lost: faults.lost }; },
    /** Whether the panel's module is here (mount() then works at once). */
    get loaded() { return mountPanel !== null; },
    load,
    mount,
    unmount,
    set,
    /** listener({ keys, source }) after every change; returns a function that removes it. */
    onChange: store.onChange,
    links: () => ({ lecture: lectureLink(values), embed: embedUrl(panel, values, embedOptions) }),
    /** The keys the link set to something other than their default. */
    urlKeys: Object.keys(schema).filter((key) => start[key] !== schema[key].default),
    /**
     * Back to the link's values ('start') or the schema's defaults ('defaults'), as a change made by the API.
     * @param {'start' | 'defaults'} [to]
     */
    reset(to = 'start') {
      const target = { ...(to === 'defaults' ? defaults(schema) : start) };
      if (ctx.reducedMotion && panel.animates) target[panel.animates] = false; // still, as it was started
      return set(target, { source: 'api' });
    },
    /**
     * lock, unlock, hide or show controls (names, or null for all); returns the unknown names.
     * @param {import('./createControlState.js').ControlChange} kind
     * @param {readonly string[] | null} names
     */
    controls: (kind, names) => controlState.change(kind, names),
    get locked() { return controlState.locked; },
    get hiddenControls() { return controlState.hidden; },
    /**
     * Reduced motion asked for by the embed (true/false) or left to the reader (null): an animation stops.
     * @param {boolean | null} on
     */
    setReducedMotion(on) {
      reducedMotion = on;
      if (on && panel.animates && values[panel.animates]) set({ [panel.animates]: false }, { source: 'api' });
    },
    /** The slide-sized poster of this view, as a PNG data URL (null before the panel mounts). */
    poster,
    /**
     * The picture as a PNG data URL (fitted into width × height when given; null for a panel
     * without one), the plotted numbers as CSV text, and the values.
     * @param {{ width?: number | null, height?: number | null }} [size]
     */
    async snapshot({ width = null, height = null } = {}) {
      const url = instance?.png?.() ?? null;
      const table = instance?.csv?.() ?? null;
      const png = url ? await resizePng(url, width, height) : null;
      return {
        png: png?.url ?? null,
        width: png?.width ?? null,
        height: png?.height ?? null,
        csv: table ? toCsv(table.columns) : null,
        csvFilename: table ? (table.filename ?? `fresnel-lab-${panel.id}.csv`) : null,
        params: { ...values },
      };
    },
  };
}
