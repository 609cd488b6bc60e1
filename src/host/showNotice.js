// @ts-check
// A visible, dismissible notice: bad input is said on screen, in words, never only in the console.
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';

const t = messages('host', english);

/**
 * The notice, first in `host`, or null when there is nothing to say (no lines).
 * @param {HTMLElement} host
 * @param {string} title
 * @param {string[]} lines  each said as text, never as markup
 * @param {{ kind?: 'warning' | 'error' }} [options]
 */
export function showNotice(host, title, lines, { kind = 'warning' } = {}) {
  if (!lines.length) return null;
  const box = document.createElement('div');
  box.className = `notice notice-${kind}`;
  box.setAttribute('role', kind === 'error' ? 'alert' : 'status');
  const heading = document.createElement('strong');
  heading.textContent = title;
  const list = document.createElement('ul');
  for (const line of lines) {
    const item = document.createElement('li');
    item.textContent = line;
    list.append(item);
  }
  const close = document.createElement('button');
  close.type = 'button';
  close.className = 'notice-close';
  close.textContent = t('dismiss');
  close.addEventListener('click', () => box.remove());
  box.append(heading, list, close);
  host.prepend(box);
  return box;
}
