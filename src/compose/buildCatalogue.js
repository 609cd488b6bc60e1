// @ts-check
// What can be added to the lecture: every panel by its title and what it shows (plain text), a
// question from the homework bank, and a text item. Each "Add" keeps the focus, so a panel can be
// added twice with two presses; the list says what was added.
import english from 'virtual:messages/en/compose';
import { messages } from '../i18n/messages.js';
import { button, el } from '../ui/el.js';
import { setSubscripted } from '../ui/subscripts.js';
import { field, titledSection } from '../ui/formParts.js';
import { panelCatalogue, questionPrompt } from './catalogue.js';
import { questionSelect } from './questionSelect.js';

const t = messages('compose', english);

/**
 * onAdd: { panel(id), question(id), text() }.
 * @param {{ panel: (id: string) => void, question: (id: string) => void, text: () => void }} onAdd
 */
export function buildCatalogue(onAdd) {
  const { section, heading } = titledSection('cp-catalogue', 'cp-catalogue-title', t('catalogueHeading'));

  const texts = el('div', 'cp-add-row');
  const addText = button(t('addText'));
  addText.addEventListener('click', () => onAdd.text());
  texts.append(addText);

  const questionBox = el('div', 'cp-add-question');
  const select = questionSelect();
  const addQuestion = button(t('addQuestion'));
  addQuestion.addEventListener('click', () => onAdd.question(select.value));
  // An option holds the prompt's start only (a select is one line wide): the whole prompt, with
  // the room's numbers, is shown below it and read out with the select.
  const preview = el('p', 'cp-prompt cp-question-preview');
  preview.id = 'cp-question-preview';
  select.setAttribute('aria-describedby', preview.id);
  const showPrompt = () => setSubscripted(preview, questionPrompt(select.value));
  select.addEventListener('change', showPrompt);
  showPrompt();
  questionBox.append(field(t('questionField'), select), preview, addQuestion);

  const panelsHeading = el('h3', 'cp-sub', t('panelsHeading'));
  panelsHeading.id = 'cp-panels-title';
  const panels = el('ul', 'cp-panels');
  panels.setAttribute('aria-labelledby', panelsHeading.id);
  for (const panel of panelCatalogue()) {
    const row = el('li', 'cp-panel');
    const name = el('h4', 'cp-panel-title');
    name.id = `cp-panel-${panel.id}`;
    setSubscripted(name, panel.title);
    const lede = el('p', 'cp-panel-lede');
    setSubscripted(lede, panel.lede);
    const add = button(t('addPanel'));
    add.dataset.panel = panel.id;
    add.setAttribute('aria-describedby', name.id);
    add.setAttribute('aria-label', t('addPanelNamed', { title: panel.title }));
    add.addEventListener('click', () => onAdd.panel(panel.id));
    row.append(name, lede, add);
    panels.append(row);
  }
  section.append(heading, texts, questionBox, panelsHeading, panels);
  return section;
}
