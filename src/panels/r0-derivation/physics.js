// The lecture's derivation of R(0°) ("Reflection Math", the θ = 0° slides), one entry per line,
// each evaluated literally as that line is written, so a panel can show that every step has the
// same value. Pure float64 math, no DOM. The lines differ only by rounding (about 1e-17).

/** Largest |a − b| over all pairs of the values: the spread of the lines. */
export function maxSpread(values) {
  return Math.max(...values) - Math.min(...values);
}

/**
 * The steps for indices nI → nT. Returns { setup, lines }:
 * setup: the values θ = 0 gives c and g ({ symbol, tex, step, value });
 * lines: the derivation of R(0°) ({ tex, step, value }), from the exact formula to
 * ((nT − nI)/(nT + nI))². `tex` is the right-hand side; the panel writes "R(0°) =" before it.
 * `step` names what the line does: the catalogue's words for it are r0-derivation's `step.<step>`.
 */
export function r0Steps(nI, nT) {
  if (!(nI > 0 && nT > 0 && Number.isFinite(nI) && Number.isFinite(nT))) {
    throw new RangeError(`indices must be finite numbers > 0, got ${nI}, ${nT}`);
  }
  const m = nI / nT;
  const c = (nI / nT) * Math.cos(0);
  const g = Math.sqrt(1 + c * c - c * c);
  const gExact = Math.sqrt(1 + c * c - m * m); // the general g at θ = 0, for the first line
  const setup = [
    {
      symbol: 'c', value: c, step: 'cosZero',
      tex: 'c = \\frac{n_i}{n_t}\\cos 0^\\circ = \\frac{n_i}{n_t}',
    },
    {
      symbol: 'g', value: g, step: 'mIsC',
      tex: 'g = \\sqrt{1 + c^2 - c^2} = 1',
    },
  ];
  const lines = [
    {
      step: 'exactAtZero',
      tex: '\\tfrac{1}{2}\\left(\\frac{g-c}{g+c}\\right)^{2}\\left(1+\\left(\\frac{c(g+c)-m^{2}}{c(g-c)+m^{2}}\\right)^{2}\\right)',
      value: 0.5 * ((gExact - c) / (gExact + c)) ** 2
        * (1 + ((c * (gExact + c) - m * m) / (c * (gExact - c) + m * m)) ** 2),
    },
    {
      step: 'putIn',
      tex: '\\tfrac{1}{2}\\left(\\frac{1-c}{1+c}\\right)^{2}\\left(1+\\left(\\frac{c(1+c)-c^{2}}{c(1-c)+c^{2}}\\right)^{2}\\right)',
      value: 0.5 * ((1 - c) / (1 + c)) ** 2 * (1 + ((c * (1 + c) - c * c) / (c * (1 - c) + c * c)) ** 2),
    },
    {
      step: 'multiplyOut',
      tex: '\\tfrac{1}{2}\\left(\\frac{1-c}{1+c}\\right)^{2}\\left(1+\\left(\\frac{c+c^{2}-c^{2}}{c-c^{2}+c^{2}}\\right)^{2}\\right)',
      value: 0.5 * ((1 - c) / (1 + c)) ** 2 * (1 + ((c + c * c - c * c) / (c - c * c + c * c)) ** 2),
    },
    {
      step: 'ratioIsOne',
      tex: '\\tfrac{1}{2}\\left(\\frac{1-c}{1+c}\\right)^{2}(2)',
      value: 0.5 * ((1 - c) / (1 + c)) ** 2 * 2,
    },
    {
      step: 'halfTimesTwo',
      tex: '\\left(\\frac{1-c}{1+c}\\right)^{2}',
      value: ((1 - c) / (1 + c)) ** 2,
    },
    {
      step: 'cIsRatio',
      tex: '\\left(\\frac{1-\\frac{n_i}{n_t}}{1+\\frac{n_i}{n_t}}\\right)^{2}',
      value: ((1 - nI / nT) / (1 + nI / nT)) ** 2,
    },
    {
      step: 'commonDenominator',
      tex: '\\left(\\frac{\\left(\\frac{n_t-n_i}{n_t}\\right)}{\\left(\\frac{n_t+n_i}{n_t}\\right)}\\right)^{2}',
      value: (((nT - nI) / nT) / ((nT + nI) / nT)) ** 2,
    },
    {
      step: 'reciprocal',
      tex: '\\left(\\left(\\frac{n_t-n_i}{n_t}\\right)\\left(\\frac{n_t}{n_t+n_i}\\right)\\right)^{2}',
      value: (((nT - nI) / nT) * (nT / (nT + nI))) ** 2,
    },
    {
      step: 'cancels',
      tex: '\\left(\\frac{n_t-n_i}{n_t+n_i}\\right)^{2}',
      value: ((nT - nI) / (nT + nI)) ** 2,
    },
  ];
  return { setup, lines };
}
