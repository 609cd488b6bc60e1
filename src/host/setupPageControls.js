// @ts-check
// The lecture page's own controls: the language, theme (dark/light), projector mode, one material
// for every panel, and hiding all controls for a clean projected picture (also the `h` key).
import english from 'virtual:messages/en/host';
import { currentLanguage, messages } from '../i18n/messages.js';
import { applyTheme, loadTheme } from '../ui/theme.js';
import { dielectrics } from '../optics/materials.js';
import { languageChoices, rememberLanguage } from '../i18n/language.js';
import { languageById } from '../i18n/languages.js';
import { fixed } from '../ui/format.js';

const t = messages('host', english);

/**
 * A select of the languages the lab speaks, each by its own name. A change is kept in this browser
 * and the page starts again in it, with ?lang= in its link: the reader's choice then beats a
 * language the page carries (a sheet's, a lecture's) as well as the browser's.
 */
export function languageSelect() {
  const select = document.createElement('select');
  select.lang = ''; // each option names its language in that language (its own lang below)
  // Those names are no words of the catalogue: the same in every language, never translated.
  select.dataset.pseudoSkip = '';
  // A pseudo-locale (asked for by link, for tests) is shown while it is the page's, so the select says what the page speaks.
  const current = languageById(currentLanguage());
  const choices = languageChoices();
  for (const language of !current || choices.includes(current) ? choices : [...choices, current]) {
    const option = new Option('', language.id, false, language.id === current?.id);
    option.label = language.name; // shown as the option's text, and no text of the page's language around it
    option.lang = language.id;
    select.add(option);
  }
  select.addEventListener('change', () => {
    rememberLanguage(select.value);
    const url = new URL(window.location.href);
    url.searchParams.set('lang', select.value);
    window.location.assign(url.toString());
  });
  return select;
}

/** A refractive index as the table of materials writes it (1.000293, 1.3333): every digit it has, the page's decimal separator. */
const materialIndex = (/** @type {number} */ n) => fixed(n, Math.max(0, (String(n).split('.')[1] ?? '').length));

/**
 * The controls, appended to `bar`. onMaterial(material): a material was picked for every panel
 * (none: a page without panels of its own, which gets no material select and no hide button).
 * @param {HTMLElement} bar
 * @param {{ onMaterial?: ((material: (typeof dielectrics)[number]) => void) | null }} [options]
 */
export function setupPageControls(bar, { onMaterial = null } = {}) {
  const theme = loadTheme();
  applyTheme(theme);

  // The name in an element of its own: the label's text is its name alone, not its options too.
  /** @param {string} text @param {HTMLElement} control */
  const label = (text, control) => {
    const wrap = document.createElement('label');
    const name = document.createElement('span');
    name.textContent = `${text} `;
    wrap.append(name, control);
    return wrap;
  };
  const scheme = document.createElement('select');
  for (const [value, text] of [['dark', t('themeDark')], ['light', t('themeLight')]]) {
    scheme.add(new Option(text, value, false, theme.scheme === value));
  }
  scheme.addEventListener('change', () => { theme.scheme = scheme.value === 'light' ? 'light' : 'dark'; applyTheme(theme); });

  const projector = document.createElement('input');
  projector.type = 'checkbox';
  projector.checked = theme.projector;
  projector.addEventListener('change', () => { theme.projector = projector.checked; applyTheme(theme); });

  const material = document.createElement('select');
  material.add(new Option(t('materialKeep'), ''));
  for (const m of dielectrics) material.add(new Option(t('materialOption', { name: m.name, n: materialIndex(m.n) }), m.id));
  material.addEventListener('change', () => {
    const chosen = dielectrics.find((m) => m.id === material.value);
    if (chosen) onMaterial?.(chosen);
  });

  const hide = document.createElement('button');
  hide.type = 'button';
  hide.textContent = t('hideControls');
  const toggleControls = () => {
    const hidden = document.body.classList.toggle('controls-hidden');
    hide.textContent = hidden ? t('showControls') : t('hideControls');
    hide.setAttribute('aria-pressed', String(hidden));
  };
  hide.addEventListener('click', toggleControls);

  // A page without panels of its own (the homework page, whose panels sit in frames) has no
  // material or controls to set.
  bar.append(label(t('language'), languageSelect()), label(t('theme'), scheme), label(t('projector'), projector),
    ...(onMaterial ? [label(t('material'), material), hide] : []));
  return { toggleControls, material };
}
