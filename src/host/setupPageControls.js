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
import { materialName } from '../panels/shared/materialName.js';

const t = messages('host', english);

/**
 * The languages the lab speaks, each a link by its own name, the page's own marked current. Links,
 * not a select that reloads on change: a keyboard reader arrowing through a select would leave the
 * page at the first press (WCAG 2.2, 3.2.2 On Input). Following one keeps the choice in this browser
 * and starts the page again in it, as it is now, with ?lang= in its link: the reader's choice then
 * beats a language the page carries (a sheet's, a lecture's) as well as the browser's.
 * @param {string} name the group's name, from the catalogue
 */
export function languageLinks(name) {
  const group = document.createElement('span');
  group.className = 'page-languages';
  group.setAttribute('role', 'group');
  const heading = document.createElement('span');
  heading.id = 'page-languages-name';
  heading.textContent = name;
  group.setAttribute('aria-labelledby', heading.id);
  group.append(heading);
  // A pseudo-locale (asked for by link, for tests) is shown while it is the page's, so the group says what the page speaks.
  const current = languageById(currentLanguage());
  const choices = languageChoices();
  /** @param {string} id */
  const linkTo = (id) => {
    const url = new URL(window.location.href);
    url.searchParams.set('lang', id);
    return url.toString();
  };
  for (const language of !current || choices.includes(current) ? choices : [...choices, current]) {
    // Each names its language in that language: no word of the catalogue, never translated.
    const here = language.id === current?.id;
    const item = document.createElement(here ? 'strong' : 'a');
    item.textContent = language.name;
    item.lang = language.id;
    if (here) item.setAttribute('aria-current', 'true');
    else if (item instanceof HTMLAnchorElement) {
      item.hreflang = language.id;
      item.href = linkTo(language.id);
      // The link as the page is now (its values follow changes in the page's own link).
      item.addEventListener('click', () => {
        rememberLanguage(language.id);
        item.href = linkTo(language.id);
      });
    }
    group.append(item);
  }
  return group;
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
  for (const m of dielectrics) material.add(new Option(t('materialOption', { name: materialName(m.id), n: materialIndex(m.n) }), m.id));
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
  bar.append(languageLinks(t('language')), label(t('theme'), scheme), label(t('projector'), projector),
    ...(onMaterial ? [label(t('material'), material), hide] : []));
  return { toggleControls, material };
}
