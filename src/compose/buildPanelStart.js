// @ts-check
// Where a panel item starts and what the room may change in it: a start state from a pasted link
// (pastedLink.js) or from the panel's current view in a preview beside the fields (the embed page
// in a frame, asked for its state through the message API: fresnel-lab:get → fresnel-lab:state),
// and each control free, locked or hidden, as the embed options have them. Values from the frame
// are checked by the panel's schema like any message.
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { button, el } from '../ui/el.js';
import { setSubscripted } from '../ui/subscripts.js';
import { fixed } from '../ui/format.js';
import { field } from '../ui/formParts.js';
import { applyParams, defaults, describeProblem, formatValue } from '../host/params.js';
import { embedLink } from '../host/embedLink.js';
import { isObject } from '../host/own.js';
import { loadTheme } from '../ui/theme.js';
import { panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';
import { readPastedLink } from './pastedLink.js';
import { panelTitle } from '../panels/panelText.js';
import { controlLabel, optionLabel } from '../panels/controlText.js';

const t = messages('compose', english);
const ANSWER_MS = 5000;

/** @typedef {import('./composerModel.js').PanelDraft} PanelDraft */
/** @typedef {import('./composerModel.js').ItemPatch} ItemPatch */
/** @typedef {import('../host/panelContract.js').Schema} Schema */

/**
 * A value of panel `id`'s `key` as its controls would show it (numbers through ui/format.js, to the link's decimals).
 * @param {string} id
 * @param {string} key
 * @param {import('../host/panelContract.js').ParamSpec} spec
 * @param {unknown} value  a value its schema accepted
 */
export function shownValue(id, key, spec, value) {
  if (spec.type === 'number' && typeof value === 'number') return fixed(value, formatValue(spec, value).split('.')[1]?.length ?? 0);
  if (spec.type === 'enum') return optionLabel(id, key, value);
  if (spec.type === 'boolean') return t('valueOnOff', { on: String(Boolean(value)) });
  if (spec.type === 'text') return t('valueText', { count: String(value).length, n: fixed(String(value).length, 0) });
  return String(value);
}

/**
 * Only the values that differ from the panel's defaults (the lecture stores no others).
 * @param {Schema} schema
 * @param {import('../host/panelContract.js').Values} values
 */
function changedValues(schema, values) {
  const start = defaults(schema);
  return Object.fromEntries(Object.entries(values).filter(([key, value]) => !Object.is(value, start[key])));
}

/**
 * The embed page's address for an item: its state, locks and hidden controls, this page's theme.
 * @param {Pick<PanelDraft, 'panel' | 'state' | 'lock' | 'hide'>} item
 */
function embedAddress(item) {
  const schema = panelSchema(item.panel) ?? {}; // a draft's panels are the manifest's (readLecture, the catalogue)
  return embedLink(new URL('./embed.html', window.location.href).href, { id: item.panel, schema },
    item.state, { lock: item.lock, hide: item.hide, theme: loadTheme().scheme });
}

/**
 * Where panel item `initial` starts, and its controls' locks; patch(fields): the item's fields changed.
 * @param {PanelDraft} initial
 * @param {{ patch: (fields: ItemPatch) => void }} options
 */
export function buildPanelStart(initial, { patch }) {
  const item = { ...initial, state: { ...initial.state }, lock: [...initial.lock], hide: [...initial.hide] };
  const schema = panelSchema(item.panel) ?? {};
  const title = panelEntry(item.panel) ? panelTitle(item.panel) : item.panel;
  const box = el('div', 'cp-start');
  const summary = el('p', 'cp-start-summary');
  const result = el('div', 'cp-start-result');
  result.setAttribute('role', 'status');

  /** @type {(lines: string[], kind?: 'ok' | 'problem') => void} */
  const say = (lines, kind = 'ok') => result.replaceChildren(...lines.map((line) => el('p', kind === 'ok' ? 'cp-ok' : 'cp-problem', line)));
  const showSummary = () => {
    const keys = Object.keys(item.state);
    summary.replaceChildren();
    if (!keys.length) summary.textContent = t('startDefaults');
    else {
      // One message with the values as a list, each value its own element (subscripts in names).
      const marker = '\u0000';
      const [before, after = ''] = t('startFrom', { values: marker }).split(marker);
      summary.append(before);
      keys.forEach((key, i) => {
        const part = el('span', 'cp-value');
        const name = schema[key] ? controlLabel(item.panel, key) : key;
        const value = schema[key] ? shownValue(item.panel, key, schema[key], item.state[key]) : '';
        setSubscripted(part, t('startValue', { name, value }));
        summary.append(part, i < keys.length - 1 ? t('startSeparator') : '');
      });
      summary.append(after);
    }
  };
  /** @type {(state: import('../host/panelContract.js').Values, extra?: { lock?: string[], hide?: string[] }) => void} */
  const setStart = (state, extra = {}) => {
    item.state = changedValues(schema, state);
    Object.assign(item, extra);
    patch({ state: { ...item.state }, ...extra });
    showSummary();
    refreshControls();
    if (frame) frame.src = embedAddress(item);
  };

  // A pasted link.
  const paste = /** @type {HTMLInputElement} */ (el('input'));
  paste.type = 'text';
  paste.placeholder = t('pastePlaceholder');
  const use = button(t('useLink'));
  const useLink = () => {
    const read = readPastedLink(paste.value, item.panel);
    if (!read.ok) { say(read.problems, 'problem'); return; }
    const locks = read.source === 'embed' || read.source === 'composed' ? { lock: read.lock, hide: read.hide } : {};
    setStart(read.state, locks);
    const taken = Object.keys(item.state).length;
    say([t('takenFromLink', { count: taken, n: fixed(taken, 0), locks: String(Boolean(locks.lock)) })]);
    if (read.problems.length) result.append(...read.problems.map((p) => el('p', 'cp-problem', t('refused', { problem: p }))));
  };
  use.addEventListener('click', useLink);
  paste.addEventListener('keydown', (event) => { if (event.key === 'Enter') { event.preventDefault(); useLink(); } });
  const reset = button(t('backToDefaults'));
  reset.addEventListener('click', () => { setStart({}); say([t('startsFromDefaults')]); });
  const pasteRow = el('div', 'cp-row');
  pasteRow.append(field(t('pasteField', { title }), paste), use, reset);

  // The preview, and its current view.
  /** @type {HTMLIFrameElement | null} */
  let frame = null;
  /** @type {number | undefined} the wait for the frame's answer to fresnel-lab:get */
  let pending;
  const preview = el('div', 'cp-preview-frame');
  const toggle = button(t('showPanel'));
  toggle.setAttribute('aria-expanded', 'false');
  const take = button(t('takeView'));
  take.disabled = true;
  /** @param {MessageEvent} event */
  const onMessage = (event) => {
    if (frame && !frame.isConnected) { // the item was removed with its preview open
      window.removeEventListener('message', onMessage);
      return;
    }
    /** @type {unknown} the frame's message, data until it is checked */
    const data = event.data;
    if (!frame || event.source !== frame.contentWindow || event.origin !== window.location.origin || !isObject(data)) return;
    const { type, height } = data;
    if (type === 'fresnel-lab:ready') take.disabled = false;
    else if (type === 'fresnel-lab:size' && typeof height === 'number' && Number.isFinite(height)) {
      frame.style.height = `${Math.min(2400, Math.max(200, Math.ceil(height) + 2))}px`;
    } else if (type === 'fresnel-lab:state' && pending && data.panel === item.panel) {
      clearTimeout(pending);
      pending = undefined;
      const params = isObject(data.params) ? data.params : {};
      const { applied, rejected } = applyParams(schema, defaults(schema), params);
      setStart(applied);
      say([t('takenFromPanel', { changed: String(Object.keys(item.state).length > 0) }),
        ...rejected.map((r) => t('refused', { problem: describeProblem({ ...r, fallback: undefined }) }))]);
    }
  };
  toggle.addEventListener('click', () => {
    if (frame) {
      frame.remove();
      frame = null;
      window.removeEventListener('message', onMessage);
      take.disabled = true;
      toggle.textContent = t('showPanel');
      toggle.setAttribute('aria-expanded', 'false');
      return;
    }
    frame = /** @type {HTMLIFrameElement} */ (el('iframe', 'cp-frame'));
    frame.title = t('previewFrame', { title });
    frame.allow = 'fullscreen; clipboard-write';
    frame.src = embedAddress(item);
    window.addEventListener('message', onMessage);
    preview.append(frame);
    toggle.textContent = t('hidePanel');
    toggle.setAttribute('aria-expanded', 'true');
  });
  take.addEventListener('click', () => {
    if (!frame?.contentWindow) return;
    clearTimeout(pending);
    pending = setTimeout(() => { pending = undefined; say([t('noAnswer')], 'problem'); }, ANSWER_MS);
    frame.contentWindow.postMessage({ type: 'fresnel-lab:get' }, window.location.origin);
  });
  const previewRow = el('div', 'cp-row');
  previewRow.append(toggle, take);

  // Each control: free, locked (shown, fixed) or hidden.
  const controls = el('details', 'cp-controls');
  const legend = el('summary', null, t('controlsHeading'));
  const grid = el('div', 'cp-control-grid');
  controls.append(legend, grid);
  /** @type {Map<string, HTMLSelectElement>} */
  const selects = new Map();
  for (const key of Object.keys(schema)) {
    const select = /** @type {HTMLSelectElement} */ (el('select'));
    for (const value of ['free', 'lock', 'hide']) select.add(new Option(t('controlState', { state: value }), value));
    const label = el('label', 'cp-control');
    const name = el('span');
    setSubscripted(name, controlLabel(item.panel, key));
    label.append(name, select);
    grid.append(label);
    selects.set(key, select);
    select.addEventListener('change', () => {
      item.lock = item.lock.filter((k) => k !== key);
      item.hide = item.hide.filter((k) => k !== key);
      if (select.value === 'lock') item.lock.push(key);
      if (select.value === 'hide') item.hide.push(key);
      patch({ lock: [...item.lock], hide: [...item.hide] });
      refreshControls();
      if (frame) frame.src = embedAddress(item);
    });
  }
  function refreshControls() {
    for (const [key, select] of selects) {
      select.value = item.hide.includes(key) ? 'hide' : item.lock.includes(key) ? 'lock' : 'free';
    }
    const n = item.lock.length + item.hide.length;
    legend.textContent = n ? t('controlsHeadingCounts', { locked: fixed(item.lock.length, 0), hidden: fixed(item.hide.length, 0) })
      : t('controlsHeading');
  }
  showSummary();
  refreshControls();
  box.append(summary, pasteRow, result, previewRow, preview, controls);
  return box;
}
