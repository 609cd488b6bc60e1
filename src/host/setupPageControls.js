// The lecture page's own controls: theme (dark/light), projector mode, one material for every
// panel, and hiding all controls for a clean projected picture (also the `h` key).
import { applyTheme, loadTheme } from '../ui/theme.js';
import { dielectrics } from '../optics/materials.js';

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
  bar.append(label('Theme ', scheme), label('Projector ', projector),
    ...(onMaterial ? [label('Material in every panel ', material), hide] : []));
  return { toggleControls, material };
}
