// lil-gui controls generated from a params schema: the schema is the single source of truth,
// the GUI only edits the values object and reports each change.
import GUI from 'lil-gui';

/**
 * Adds one controller per schema key (or per key in `keys`) to `gui`, editing `values` in place.
 * onChange(key, value) runs on every change; returns { key: controller }.
 */
export function bindGui(gui, schema, values, onChange, keys = Object.keys(schema)) {
  const controllers = {};
  for (const key of keys) {
    const spec = schema[key];
    let controller;
    if (spec.type === 'number') controller = gui.add(values, key, spec.min, spec.max, spec.step);
    else if (spec.type === 'enum') {
      // Schemas list options as values or as { value: label }; lil-gui wants { label: value }.
      const options = Array.isArray(spec.options)
        ? spec.options
        : Object.fromEntries(Object.entries(spec.options).map(([value, label]) => [label, value]));
      controller = gui.add(values, key, options);
    }
    else if (spec.type === 'color') controller = gui.addColor(values, key);
    else controller = gui.add(values, key);
    controller.name(spec.label ?? key).onChange((value) => onChange(key, value));
    controllers[key] = controller;
  }
  return controllers;
}

/** A GUI placed inside the panel (not floating over the page), keyboard-operable like any form. */
export function createPanelGui(container, title) {
  return new GUI({ container, title, width: 360 });
}
