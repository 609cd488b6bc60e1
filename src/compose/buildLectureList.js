// @ts-check
// The lecture's items as an ordered list (<ol>) of cards. Each card is focusable and is moved by
// its Move up / Move down buttons, by Alt+↑ / Alt+↓ anywhere in it (but in a select), or by dragging its handle with
// a pointer; ↑ and ↓ on a card itself go to the card above or below. A move keeps the focus where
// it was (on the card or the button), and a polite live region says where the item went. The cards
// are kept per item key, so an editor being typed in is never rebuilt by a move.
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { button, el } from '../ui/el.js';
import { itemKind, itemName } from './composerModel.js';
import { fixed } from '../ui/format.js';

const t = messages('compose', english);

/**
 * actions: { move(key, delta), moveTo(key, index), duplicate(key), remove(key) }; editor(item):
 * the element that edits an item (built once per key). Returns { element, status, sync(draft),
 * reset(draft), focusItem(key), announce(text) }.
 * @param {{ actions: { move: (key: string, delta: number) => void, moveTo: (key: string, index: number) => void,
 *   duplicate: (key: string) => void, remove: (key: string) => void },
 *   editor: (item: import('./composerModel.js').ItemDraft) => Node }} options
 */
export function buildLectureList({ actions, editor }) {
  const list = el('ol', 'cp-list');
  list.setAttribute('aria-label', t('listLabel'));
  const empty = el('p', 'cp-empty', t('listEmpty'));
  const status = el('p', 'cp-status');
  status.setAttribute('role', 'status');
  status.setAttribute('aria-live', 'polite');
  const element = el('div', 'cp-list-box');
  element.append(status, empty, list);

  /**
   * @type {Map<string, {
   *   card: HTMLLIElement, number: HTMLElement, name: HTMLElement, up: HTMLButtonElement, down: HTMLButtonElement
   * }>}
   */
  const cards = new Map();
  /** @type {string[]} the items' keys in the list's order */
  let order = [];
  /** @type {(key: string) => HTMLLIElement | undefined} */
  const cardOf = (key) => cards.get(key)?.card;

  const announce = (/** @type {string} */ text) => { status.textContent = text; };
  /** @type {(control: HTMLButtonElement, run: () => void) => void} */
  const press = (control, run) => control.addEventListener('click', () => { if (control.getAttribute('aria-disabled') !== 'true') run(); });

  /** @param {import('./composerModel.js').ItemDraft} item */
  function makeCard(item) {
    const card = /** @type {HTMLLIElement} */ (el('li', `cp-item cp-item-${item.type}`));
    card.tabIndex = 0;
    card.dataset.key = item.key;
    const head = el('div', 'cp-item-head');
    const handle = el('span', 'cp-handle', '⠿');
    handle.setAttribute('aria-hidden', 'true');
    handle.title = t('dragHandle');
    const title = el('h3', 'cp-item-title');
    title.id = `cp-title-${item.key}`;
    card.setAttribute('aria-labelledby', title.id);
    const number = el('span', 'cp-number');
    const name = el('span', 'cp-name');
    title.append(number, el('span', 'cp-kind', itemKind(item.type)), name);
    const up = /** @type {HTMLButtonElement} */ (button(t('moveUp')));
    const down = /** @type {HTMLButtonElement} */ (button(t('moveDown')));
    const copy = button(t('duplicate'));
    const remove = button(t('remove'), 'cp-remove');
    const tools = el('div', 'cp-item-tools');
    for (const control of [up, down, copy, remove]) control.setAttribute('aria-describedby', title.id);
    tools.append(up, down, copy, remove);
    head.append(handle, title, tools);
    card.append(head, editor(item));
    press(up, () => actions.move(item.key, -1));
    press(down, () => actions.move(item.key, 1));
    copy.addEventListener('click', () => actions.duplicate(item.key));
    remove.addEventListener('click', () => actions.remove(item.key));
    card.addEventListener('keydown', (event) => {
      // Alt+↓ opens a select's list on some systems: that key stays the select's.
      if (event.altKey && (event.key === 'ArrowUp' || event.key === 'ArrowDown') && !(event.target instanceof HTMLSelectElement)) {
        event.preventDefault();
        actions.move(item.key, event.key === 'ArrowUp' ? -1 : 1);
      } else if (event.target === card && !event.altKey && (event.key === 'ArrowUp' || event.key === 'ArrowDown')) {
        event.preventDefault();
        const next = order[order.indexOf(item.key) + (event.key === 'ArrowUp' ? -1 : 1)];
        if (next) cardOf(next)?.focus();
      }
    });
    dragByHandle(handle, card, item.key);
    return { card, number, name, up, down };
  }

  // Dragging by the handle (pointer events, so mouse, pen and touch alike): the card under the
  // pointer is marked, and on release the item takes that card's place.
  /**
   * @param {HTMLElement} handle
   * @param {HTMLElement} card
   * @param {string} key
   */
  function dragByHandle(handle, card, key) {
    let target = -1;
    const mark = (/** @type {number} */ index) => {
      order.forEach((k, i) => cardOf(k)?.classList.toggle('cp-drop-target', i === index && k !== key));
      target = index;
    };
    handle.addEventListener('pointerdown', (event) => {
      if (event.button !== 0) return;
      event.preventDefault();
      handle.setPointerCapture(event.pointerId);
      card.classList.add('cp-dragging');
      mark(order.indexOf(key));
    });
    handle.addEventListener('pointermove', (event) => {
      if (!handle.hasPointerCapture(event.pointerId)) return;
      const index = order.findIndex((k) => {
        const box = cardOf(k)?.getBoundingClientRect();
        return box !== undefined && event.clientY < box.bottom;
      });
      mark(index < 0 ? order.length - 1 : index);
    });
    /** @type {(event: PointerEvent, drop: boolean) => void} */
    const end = (event, drop) => {
      if (!handle.hasPointerCapture(event.pointerId)) return;
      handle.releasePointerCapture(event.pointerId);
      card.classList.remove('cp-dragging');
      const to = target;
      mark(-1);
      if (drop && to >= 0 && to !== order.indexOf(key)) {
        actions.moveTo(key, to);
        card.focus();
      }
    };
    handle.addEventListener('pointerup', (event) => end(event, true));
    handle.addEventListener('pointercancel', (event) => end(event, false));
  }

  /**
   * The list as the draft has it: cards made for new items, dropped for removed ones, moved in place.
   * @param {import('./composerModel.js').Draft} draft
   */
  function sync(draft) {
    const active = document.activeElement;
    const keys = draft.items.map((item) => item.key);
    for (const [key, entry] of cards) {
      if (!keys.includes(key)) {
        entry.card.remove();
        cards.delete(key);
      }
    }
    draft.items.forEach((item, i) => {
      const entry = cards.get(item.key) ?? makeCard(item);
      cards.set(item.key, entry);
      if (list.children[i] !== entry.card) list.insertBefore(entry.card, list.children[i] ?? null);
      entry.number.textContent = t('itemNumber', { n: fixed(i + 1, 0) });
      entry.name.textContent = itemName(item);
      entry.name.classList.toggle('cp-name-own', item.type === 'text'); // the lecturer's own words
      entry.up.setAttribute('aria-disabled', String(i === 0));
      entry.down.setAttribute('aria-disabled', String(i === keys.length - 1));
    });
    order = keys;
    empty.hidden = keys.length > 0;
    // An element taken out and put back loses the focus: give it back.
    if (active instanceof HTMLElement && active !== document.activeElement && active.isConnected) active.focus();
  }

  /** @param {import('./composerModel.js').Draft} draft */
  function reset(draft) {
    for (const { card } of cards.values()) card.remove();
    cards.clear();
    sync(draft);
  }

  const focusItem = (/** @type {string} */ key) => cardOf(key)?.focus();
  return { element, status, sync, reset, focusItem, announce };
}
