// @ts-check
// A select of the homework bank's questions, grouped by panel, each by its kind and prompt: the
// catalogue's (to add one) and a question item's (to change it).
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { el } from '../ui/el.js';
import { questionCatalogue } from './catalogue.js';

const t = messages('compose', english);

const MAX_PROMPT = 110; // characters of a prompt shown in an option; the rest is cut

/** A select of the bank's questions (prompts cut at MAX_PROMPT characters). */
export function questionSelect() {
  const select = /** @type {HTMLSelectElement} */ (el('select'));
  for (const group of questionCatalogue()) {
    const optgroup = /** @type {HTMLOptGroupElement} */ (el('optgroup'));
    optgroup.label = group.title;
    for (const q of group.questions) {
      const prompt = q.prompt.length > MAX_PROMPT ? `${q.prompt.slice(0, MAX_PROMPT)}…` : q.prompt;
      optgroup.append(new Option(t('questionOption', { kind: q.kind, prompt }), q.id));
    }
    select.append(optgroup);
  }
  return select;
}
