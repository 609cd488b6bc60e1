// The lecture page's own controls: the language, theme (dark/light), projector mode, one material
// for every panel, and hiding all controls for a clean projected picture (also the `h` key).
import { applyTheme, loadTheme } from '../ui/theme.js';
import { dielectrics } from '../optics/materials.js';
import { languageChoices, rememberLanguage } from '../i18n/language.js';
import { currentLanguage } from '../i18n/messages.js';

/**
 * A select of the languages the lab speaks, each by its own name. A change is kept in this browser
 * and the page starts again in it, with ?lang= in its link: the reader's choice then beats a
 * language the page carries (a sheet's, a lecture's) as well as the browser's.
 */
export function languageSelect() {
  const select = document.createElement('select');
  select.lang = ''; // each option names its language in that language (its own lang below)
  for (const language of languageChoices()) {
    const option = new Option(language.name, language.id, false, language.id === currentLanguage());
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

export function setupPageControls(bar, { onMaterial = null } = {}) {
  const theme = loadTheme();
  applyTheme(theme);

  const label = (text, control) => {
    const wrap = document.createElement('label');
    wrap.append(document.createTextNode(text), control);
    return wrap;
  };
  const scheme = document.createElement('select');
  for (const [value, text] of [['dark', 'Dark'], ['light', 'Light']]) scheme.add(new Option(text, value, false, theme.scheme === value));
  scheme.addEventListener('change', () => { theme.scheme = scheme.value; applyTheme(theme); });

  const projector = document.createElement('input');
  projector.type = 'checkbox';
  projector.checked = theme.projector;
  projector.addEventListener('change', () => { theme.projector = projector.checked; applyTheme(theme); });

  const material = document.createElement('select');
  material.add(new Option('— keep each panel’s —', ''));
  for (const m of dielectrics) material.add(new Option(`${m.name} (n = ${m.n})`, m.id));
  material.addEventListener('change', () => {
    const chosen = dielectrics.find((m) => m.id === material.value);
    if (chosen) onMaterial(chosen);
  });

  const hide = document.createElement('button');
  hide.type = 'button';
  hide.textContent = 'Hide controls (h)';
  const toggleControls = () => {
    const hidden = document.body.classList.toggle('controls-hidden');
    hide.textContent = hidden ? 'Show controls (h)' : 'Hide controls (h)';
    hide.setAttribute('aria-pressed', String(hidden));
  };
  hide.addEventListener('click', toggleControls);

  // A page without panels of its own (the homework page, whose panels sit in frames) has no
  // material or controls to set.
  bar.append(label('Language ', languageSelect()), label('Theme ', scheme), label('Projector ', projector),
    ...(onMaterial ? [label('Material in every panel ', material), hide] : []));
  return { toggleControls, material };
}
