// The frame around every panel: it owns the panel's values (from the URL, validated against the
// schema), its controls, toolbar (copy link, copy embed code, PNG, CSV), its text description, and
// mounting and disposing the panel's view. Values outlive the view, so a panel that is disposed
// to free its WebGL context comes back exactly as it was.
import { applyParams, describeProblem } from './params.js';
import { bindGui, createPanelGui } from './bindGui.js';
import { readUrlState, urlWriter } from './urlState.js';
import { showNotice } from './notices.js';
import { copyText, downloadText, downloadUrl, toCsv } from './exporters.js';
import { embedCode, embedUrl, lectureUrl } from './shareLinks.js';
import { el } from './el.js';

let nextDescriptionId = 0;

/**
 * container: where the panel lives (a section's .panel-mount, or the embed root).
 * module: { id, title, schema, usesWebGL, materialParam, mount(root, ctx) }.
 * prefix: URL key prefix ('' for the hero and embeds, 'id.' for other lecture-page panels).
 */
export function createPanelHost(container, module, {
  prefix = '', noticeHost = container, onFrame = () => {}, applyMaterial = () => {},
} = {}) {
  const { values, problems } = readUrlState(module.schema, prefix);
  showNotice(noticeHost, 'Some values in the link were not usable:', problems.map(describeProblem));
  const writeUrl = urlWriter(module.schema, prefix);

  const shell = el('div', 'panel-shell');
  const content = el('div', 'panel-content');
  const side = el('div', 'panel-side');
  const guiHost = el('div', 'gui-host');
  const toolbar = el('div', 'toolbar');
  const status = el('span', 'toolbar-status');
  status.setAttribute('role', 'status');
  const description = el('p', 'panel-description');
  description.id = `panel-description-${(nextDescriptionId += 1)}`;
  side.append(guiHost, toolbar);
  shell.append(content, side);
  container.append(shell, description);

  const buttons = {
    link: el('button', '', 'Copy link'),
    embed: el('button', '', 'Copy embed code'),
    png: el('button', '', 'Export PNG'),
    csv: el('button', '', 'Export CSV'),
  };
  for (const b of Object.values(buttons)) b.type = 'button';
  toolbar.append(...Object.values(buttons), status);

  let instance = null;
  let gui = null;
  let controllers = {};
  let frames = 0;

  const say = (text) => {
    status.textContent = text;
    setTimeout(() => { if (status.textContent === text) status.textContent = ''; }, 2500);
  };
  buttons.link.addEventListener('click', async () => {
    say((await copyText(lectureUrl(module, values))) ? 'Link copied' : '');
  });
  buttons.embed.addEventListener('click', async () => {
    say((await copyText(embedCode(module, values))) ? 'Embed code copied' : '');
  });
  buttons.png.addEventListener('click', () => {
    const url = instance?.png?.();
    if (url) downloadUrl(`fresnel-lab-${module.id}.png`, url);
  });
  buttons.csv.addEventListener('click', () => {
    const table = instance?.csv?.();
    if (table) downloadText(table.filename ?? `fresnel-lab-${module.id}.csv`, toCsv(table.columns));
  });

  function refreshDescription() {
    description.textContent = instance ? instance.describe() : '';
    for (const canvas of content.querySelectorAll('canvas')) canvas.setAttribute('aria-describedby', description.id);
  }

  /** Values changed (by a control, a message, the page): redraw, re-describe, rewrite the URL. */
  function changed(keys) {
    for (const key of keys) controllers[key]?.updateDisplay();
    instance?.update(keys);
    refreshDescription();
    writeUrl(values);
  }

  const ctx = {
    values,
    get gui() { return gui; },
    /** Controllers for these schema keys in a lil-gui folder (or the root). */
    bind(folder, keys) {
      const made = bindGui(folder ?? gui, module.schema, values, (key) => changed([key]), keys);
      Object.assign(controllers, made);
      return made;
    },
    /** The panel changed values itself (a drag, a click on a table row). */
    changed,
    /** The panel drew a frame. */
    frameDrawn() {
      frames += 1;
      onFrame(frames);
    },
    /** Apply a material ({ id, name, n }) to every panel of the page (or this one in an embed). */
    applyMaterial: (material) => applyMaterial(material),
    reducedMotion: window.matchMedia?.('(prefers-reduced-motion: reduce)').matches ?? false,
  };

  const host = {
    id: module.id,
    module,
    values,
    usesWebGL: Boolean(module.usesWebGL),
    get mounted() { return instance !== null; },
    get instance() { return instance; },
    get frames() { return frames; },
    mount() {
      if (instance) return instance;
      container.style.minHeight = '';
      gui = createPanelGui(guiHost, `${module.title}: controls`);
      controllers = {};
      try {
        instance = module.mount(content, ctx);
      } catch (error) {
        gui.destroy();
        gui = null;
        showNotice(noticeHost, `The ${module.id} panel could not start.`, [error.message], { kind: 'error' });
        throw error;
      }
      buttons.png.disabled = !instance.png;
      buttons.csv.disabled = !instance.csv;
      refreshDescription();
      return instance;
    },
    unmount() {
      if (!instance) return;
      container.style.minHeight = `${container.offsetHeight}px`; // no layout jump while it is away
      instance.dispose();
      instance = null;
      gui?.destroy();
      gui = null;
      controllers = {};
      content.replaceChildren();
    },
    /** Validated partial update, as from a message or the page-wide material. */
    set(update) {
      const result = applyParams(module.schema, values, update);
      const keys = Object.keys(result.applied);
      if (keys.length) changed(keys);
      return result;
    },
    links: () => ({ lecture: lectureUrl(module, values), embed: embedUrl(module, values) }),
  };
  return host;
}
