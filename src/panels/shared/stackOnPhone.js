// Two views drawn side by side by one shader, stacked one above the other on a phone: the stage
// takes `className` (its CSS makes it twice as tall as one 4:3 half) and the shader its uStacked
// uniform, kept in step with the phone width as it changes (a tablet turned, a window resized).
import { phoneWidth } from '../../ui/phoneWidth.js';

/**
 * stage: the element around the canvas; view: a createShaderView with a uStacked uniform, or null
 * where WebGL2 is missing (the stage then keeps its wide shape for the fallback message).
 * Returns { stacked(), dispose() }.
 */
export function stackOnPhone(stage, className, view) {
  const phone = phoneWidth();
  const arrange = () => {
    stage.classList.toggle(className, phone.matches && Boolean(view));
    if (!view) return;
    view.uniforms.uStacked.value = phone.matches ? 1 : 0;
    view.render();
  };
  phone.addEventListener('change', arrange);
  arrange();
  return {
    stacked: () => view?.uniforms.uStacked.value === 1,
    dispose: () => phone.removeEventListener('change', arrange),
  };
}
