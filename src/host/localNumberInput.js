// @ts-check
// A lil-gui number field in the page's language: shown with its decimal comma where the language
// writes one (es: 1,5), and read with a comma or a point as typed, in every language: a reader in a
// German browser types 1,7 into an English page too, and no control takes thousands. lil-gui reads
// its field with parseFloat, which stops at a comma, so while the field has the focus it holds the
// point form: a comma typed is turned into a point as it is typed, and the arrow keys step from the
// value.
import { shownDecimal } from '../ui/format.js';

/** @param {{ $input?: HTMLInputElement, updateDisplay: () => unknown }} controller a lil-gui NumberController */
export function localNumberInput(controller) {
  const input = controller.$input;
  if (!input) return;
  input.inputMode = 'decimal';
  const separator = shownDecimal();
  const toPoint = () => {
    const pointed = input.value.replaceAll(',', '.').replaceAll(separator, '.');
    if (pointed === input.value) return;
    const at = input.selectionStart;
    input.value = pointed;
    if (at !== null) input.setSelectionRange(at, at);
  };
  // Capture listeners on the field itself run before lil-gui's own (added without capture).
  input.addEventListener('focus', toPoint, true);
  input.addEventListener('input', toPoint, true);
  if (separator === '.') return;
  const update = controller.updateDisplay.bind(controller);
  controller.updateDisplay = () => {
    const result = update();
    if (document.activeElement !== input) input.value = input.value.replace('.', separator);
    return result;
  };
  controller.updateDisplay();
}
