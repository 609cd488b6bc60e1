// @ts-check
// Form pieces the lab's pages share (the homework page, the composer, a question's card): a
// labelled field, a titled section, and a file read with a size limit. Text only (textContent),
// never markup. Styles: formParts.css (.ui-field).
import { el } from './el.js';
import './formParts.css';
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';

const t = messages('ui', english);

/**
 * A section named by its heading: { section, heading }.
 * @param {string} className
 * @param {string} id
 * @param {string} title
 */
export function titledSection(className, id, title) {
  const section = el('section', className);
  section.setAttribute('aria-labelledby', id);
  const heading = el('h2', null, title);
  heading.id = id;
  return { section, heading };
}

/**
 * A label whose visible text names the control (its accessible name); `className` adds classes of the page's own.
 * @param {string} labelText
 * @param {Node} control
 */
export function field(labelText, control, className = '') {
  const label = el('label', className ? `ui-field ${className}` : 'ui-field');
  label.append(el('span', null, labelText), control);
  return label;
}

const MAX_FILE_BYTES = 1_000_000; // a sheet or a handed-in file is a few kilobytes

/**
 * { ok: true, text } or { ok: false, problems }, for a file the user picked.
 * @param {File} file
 * @returns {Promise<{ ok: true, text: string, problems?: undefined } | { ok: false, problems: string[], text?: undefined }>}
 */
export async function readTextFile(file) {
  if (file.size > MAX_FILE_BYTES) return { ok: false, problems: [t('file.tooLarge', { name: file.name, size: file.size })] };
  try {
    return { ok: true, text: await file.text() };
  } catch {
    return { ok: false, problems: [t('file.unreadable', { name: file.name })] };
  }
}
