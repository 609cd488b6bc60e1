// Whether values are ones a schema could hold, judged here and not by src/host/params.js (which is
// what the tests that use this check).

/** Whether `value` is one the schema could hold for `spec`. */
export function validValue(spec, value) {
  switch (spec.type) {
    case 'number':
      return typeof value === 'number' && Number.isFinite(value) && value >= spec.min && value <= spec.max
        && (!spec.integer || Number.isInteger(value)) && !Object.is(value, -0);
    case 'enum': {
      const values = Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options);
      return typeof value === 'string' && values.includes(value);
    }
    case 'color': return typeof value === 'string' && /^#[0-9a-f]{6}$/.test(value);
    case 'boolean': return typeof value === 'boolean';
    case 'text': return typeof value === 'string' && value.length <= spec.maxLength;
    default: return false;
  }
}

/** Every key of the schema and no other, each with a value it could hold. */
export const validValues = (schema, values) => Object.keys(values).length === Object.keys(schema).length
  && Object.entries(schema).every(([key, spec]) => Object.hasOwn(values, key) && validValue(spec, values[key]));
