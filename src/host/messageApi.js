// @ts-check
// The message API between a slide deck (or any page) and an embedded panel, version 1
// (window.postMessage; docs/deck/messages.md has the table). Deck → panel:
//   {type:'fresnel-lab:set', params}              validated; rejected values answer fresnel-lab:error
//   {type:'fresnel-lab:get'}                      answers fresnel-lab:state
//   {type:'fresnel-lab:reset', to?}               to 'start' (the embed URL's values, the default) or 'defaults'
//   {type:'fresnel-lab:snapshot', width?, height?, id?}  answers fresnel-lab:snapshot {png, csv, params}
//   {type:'fresnel-lab:lock' | 'unlock' | 'hide' | 'show', keys?}  controls; no keys: all of them
//   {type:'fresnel-lab:theme', theme} · {type:'fresnel-lab:projector', on} · {type:'fresnel-lab:reducedMotion', on}
//   {type:'fresnel-lab:language', lang}          the panel starts again in that language (its state is in its link)
//   {type:'fresnel-lab:audio', on}                the audio trace of the R(θ) plots
//   {type:'fresnel-lab:pause'} · {type:'fresnel-lab:resume'}, and reveal.js's plain 'slide:stop' / 'slide:start'
// Panel → deck: fresnel-lab:ready {apiVersion, panel, params}; fresnel-lab:changed {source, keys,
// params} after every change (gathered for CHANGED_MS during a drag); fresnel-lab:state (as before
// version 1, after get, set and changes not made by the API); fresnel-lab:rendered {frame};
// fresnel-lab:error {message}; fresnel-lab:key {key} (keys no control used, for a deck's clicker);
// fresnel-lab:size {height} (the page's content height in CSS pixels, so a host can fit the frame);
// fresnel-lab:audio {on} when the reader turned the audio trace on or off.
// Anything else is ignored. Nothing from a message is evaluated or inserted as HTML.

import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { rawText } from './params.js';
import { isObject } from './own.js';

const t = messages('host', english);

export const API_VERSION = 1;

/** How long changes are gathered into one `changed` message (a slider drag sends a few a second). */
export const CHANGED_MS = 80;

/** @typedef {import('./createControlState.js').ControlChange} ControlChange */

/**
 * A message the panel takes, as parseMessage reads it.
 * @typedef {{ kind: 'get' | 'pause' | 'resume' }
 *   | { kind: 'set', params: Record<string, unknown> }
 *   | { kind: 'reset', to: 'start' | 'defaults' }
 *   | { kind: 'snapshot', width: number | null, height: number | null, id: string | null }
 *   | { kind: 'theme', theme: 'light' | 'dark' }
 *   | { kind: 'language', lang: string }
 *   | { kind: 'projector' | 'reducedMotion' | 'audio', on: boolean }
 *   | { kind: ControlChange, keys: string[] | null }} Message
 */

/** @type {readonly string[]} */
const CONTROL_KINDS = ['lock', 'unlock', 'hide', 'show'];
const MAX_SNAPSHOT = 4096;

/** @type {(kind: string) => kind is ControlChange} */
const isControlChange = (kind) => CONTROL_KINDS.includes(kind);

/**
 * keys: absent (all), or a list of up to 64 short strings; anything else is not a message.
 * @param {unknown} keys
 * @returns {{ ok: true, keys: string[] | null } | { ok: false, keys?: undefined }}
 */
function keyList(keys) {
  if (keys === undefined || keys === null) return { ok: true, keys: null };
  if (!Array.isArray(keys) || keys.length > 64 || !keys.every((k) => typeof k === 'string' && k.length <= 64)) return { ok: false };
  return { ok: true, keys };
}

/** A snapshot's side: null when absent, undefined when it is not a size. @param {unknown} v */
const size = (v) => (v === undefined ? null : typeof v === 'number' && Number.isInteger(v) && v >= 1 && v <= MAX_SNAPSHOT ? v : undefined);

/**
 * The message as { kind, … } when it has one of the accepted shapes, else null.
 * @param {unknown} data
 * @returns {Message | null}
 */
export function parseMessage(data) {
  if (data === 'slide:start') return { kind: 'resume' };
  if (data === 'slide:stop') return { kind: 'pause' };
  if (!isObject(data) || typeof data.type !== 'string' || !data.type.startsWith('fresnel-lab:')) return null;
  const kind = data.type.slice('fresnel-lab:'.length);
  switch (kind) {
    case 'get':
    case 'pause':
    case 'resume':
      return { kind };
    case 'set':
      return isObject(data.params) ? { kind, params: data.params } : null;
    case 'reset':
      if (data.to === undefined || data.to === 'start') return { kind, to: 'start' };
      return data.to === 'defaults' ? { kind, to: data.to } : null;
    case 'snapshot': {
      const width = size(data.width);
      const height = size(data.height);
      if (width === undefined || height === undefined) return null;
      const id = typeof data.id === 'string' || typeof data.id === 'number' ? String(data.id).slice(0, 64) : null;
      return { kind, width, height, id };
    }
    case 'theme':
      return data.theme === 'light' || data.theme === 'dark' ? { kind, theme: data.theme } : null;
    case 'language':
      // A language tag, checked by the page against the languages it speaks (src/i18n/languages.js).
      return typeof data.lang === 'string' && /^[A-Za-z]{2,3}(-[A-Za-z0-9]{2,8})*$/.test(data.lang) ? { kind, lang: data.lang } : null;
    case 'projector':
    case 'reducedMotion':
    case 'audio':
      return typeof data.on === 'boolean' ? { kind, on: data.on } : null;
    default: {
      if (!isControlChange(kind)) return null;
      const list = keyList(data.keys);
      return list.ok ? { kind, keys: list.keys } : null;
    }
  }
}

/**
 * Plain copy of the values (no prototype, no functions) for posting.
 * @param {Readonly<import('./panelContract.js').Values>} values
 * @returns {import('./panelContract.js').Values}
 */
function plain(values) {
  return JSON.parse(JSON.stringify(values));
}

/**
 * What the embed page does for the page-wide messages.
 * @typedef {{ theme?: (scheme: 'light' | 'dark') => void, language?: (lang: string) => void,
 *   projector?: (on: boolean) => void, reducedMotion?: (on: boolean) => void, audio?: (on: boolean) => void,
 *   pause?: () => void, resume?: () => void }} PageHooks
 */

/**
 * Connects `host` to the messages of its parent page. origin: the deck's origin from
 * `?parentOrigin=` (messages go only there and only its messages are heard), 'none' (an unusable
 * parentOrigin: nothing is posted and nothing heard), or '*'. page: what
 * the embed page does for the page-wide messages: { theme(scheme), projector(on),
 * reducedMotion(on), audio(on), language(lang), pause(), resume() }.
 * @param {Pick<import('./createPanelHost.js').PanelHost, 'id' | 'values' | 'set' | 'reset' | 'snapshot' | 'controls' | 'onChange'
 *   | 'urlKeys'>} host
 * @param {{ parent?: Window | null, origin?: string, page?: PageHooks }} [options]
 */
export function connectMessages(host, { parent = window.parent, origin = '*', page = {} } = {}) {
  /** @param {Window | null} target @param {object} message */
  const post = (target, message) => { if (origin !== 'none') target?.postMessage(message, origin); };
  /** @param {object} message */
  const announce = (message) => { if (parent && parent !== window) post(parent, message); };
  const state = () => ({ type: 'fresnel-lab:state', panel: host.id, params: plain(host.values) });

  /** @param {Message} message @param {Window | null} reply */
  async function answer(message, reply) {
    /** @param {object} m */
    const say = (m) => post(reply, m);
    /** @param {string} text */
    const sayError = (text) => say({ type: 'fresnel-lab:error', panel: host.id, message: text });
    switch (message.kind) {
      case 'get':
        say(state());
        return;
      case 'set': {
        const { rejected } = host.set(message.params, { source: 'api' });
        if (rejected.length) {
          const list = rejected.map((r) => t('apiRejectedValue', { key: rawText(r.key), raw: rawText(r.raw), reason: r.reason }));
          sayError(t('apiRejected', { list: list.join('; ') }));
        }
        say(state());
        return;
      }
      case 'reset':
        host.reset(message.to);
        say(state());
        return;
      case 'snapshot': {
        const shot = await host.snapshot({ width: message.width, height: message.height });
        say({ type: 'fresnel-lab:snapshot', panel: host.id, id: message.id, ...shot });
        return;
      }
      case 'lock':
      case 'unlock':
      case 'hide':
      case 'show': {
        const unknown = host.controls(message.kind, message.keys);
        if (unknown.length) sayError(t('apiNoControl', { names: unknown.map((k) => k.slice(0, 40)).join(', ') }));
        return;
      }
      case 'theme':
        page.theme?.(message.theme);
        return;
      case 'language':
        page.language?.(message.lang);
        return;
      case 'projector':
      case 'reducedMotion':
      case 'audio':
        page[message.kind]?.(message.on);
        return;
      default:
        page[message.kind]?.();
    }
  }

  /** @param {MessageEvent} event */
  const onMessage = (event) => {
    if (origin === 'none' || (origin !== '*' && event.origin !== origin)) return;
    const message = parseMessage(event.data);
    // A message posted by a page: its source is that page's window (ports and workers post through other APIs).
    if (message) answer(message, /** @type {Window | null} */ (event.source) ?? parent);
  };
  window.addEventListener('message', onMessage);

  // Every change, gathered for CHANGED_MS per source (a timer, not an animation frame: a frame
  // off screen or on a hidden slide gets none). Changes the deck did not ask for also send
  // `state`, as before version 1.
  /** @type {Map<import('./panelContract.js').ChangeSource, Set<string>>} */
  const gathered = new Map();
  let timer = 0;
  const flush = () => {
    timer = 0;
    for (const [source, keys] of gathered) {
      const params = plain(host.values);
      announce({ type: 'fresnel-lab:changed', panel: host.id, source, keys: [...keys], params });
      if (source !== 'api') announce({ type: 'fresnel-lab:state', panel: host.id, params });
    }
    gathered.clear();
  };
  const stopListening = host.onChange(({ keys, source }) => {
    const set = gathered.get(source) ?? new Set();
    gathered.set(source, set);
    keys.forEach((k) => set.add(k));
    timer ||= setTimeout(flush, CHANGED_MS);
  });

  // Clicker and arrow keys that nothing in the panel used go to the deck, so a presenter's
  // Page Down still moves the slides after a click in the panel (hakimel/reveal.js#1619).
  const FORWARDED = ['PageDown', 'PageUp', ' ', 'ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', 'Home', 'End'];
  /** @param {KeyboardEvent} event */
  const onKey = (event) => {
    if (event.defaultPrevented || !FORWARDED.includes(event.key) || event.ctrlKey || event.metaKey || event.altKey) return;
    const target = /** @type {HTMLElement} */ (event.target);
    // A key a panel's canvas or diagram uses is defaultPrevented; form fields use theirs unasked,
    // and Space presses a focused button.
    if (target?.closest?.('input, select, textarea, [contenteditable]')) return;
    if (event.key === ' ' && target?.closest?.('button, [role="button"], summary, a[href]')) return;
    announce({ type: 'fresnel-lab:key', panel: host.id, key: event.key, shiftKey: event.shiftKey });
  };
  window.addEventListener('keydown', onKey);

  return {
    /** Mounted: ready, then (when the link set any values) what the link changed, as source 'url'. */
    ready() {
      const params = plain(host.values);
      announce({ type: 'fresnel-lab:ready', apiVersion: API_VERSION, panel: host.id, params });
      if (host.urlKeys?.length) announce({ type: 'fresnel-lab:changed', panel: host.id, source: 'url', keys: host.urlKeys, params });
    },
    rendered: (/** @type {number} */ frame) => announce({ type: 'fresnel-lab:rendered', panel: host.id, frame }),
    size: (/** @type {number} */ height) => announce({ type: 'fresnel-lab:size', panel: host.id, height }),
    audio: (/** @type {boolean} */ on) => announce({ type: 'fresnel-lab:audio', panel: host.id, on }),
    disconnect() {
      window.removeEventListener('message', onMessage);
      window.removeEventListener('keydown', onKey);
      stopListening();
      clearTimeout(timer);
    },
  };
}
