// A maximum read off a grid is only as good as the grid's step (0.25° on a 361-sample curve), so
// before it is shown it is refined by golden-section search between the grid neighbours of the
// largest sample (Kiefer, Proc. AMS 4, 1953; Press et al., Numerical Recipes, 3rd ed., §10.2): every
// digit printed then holds. A maximum at a kink (Schlick's error at the critical angle) is found too.

const INVERSE_PHI = (Math.sqrt(5) - 1) / 2;

/**
 * θ in [a, b] where f is largest, f taken to be unimodal there, to within `tolerance`.
 * @param {(theta: number) => number} f
 * @param {number} a
 * @param {number} b
 */
export function goldenMax(f, a, b, tolerance = 1e-10) {
  let lo = a;
  let hi = b;
  let c = hi - INVERSE_PHI * (hi - lo);
  let d = lo + INVERSE_PHI * (hi - lo);
  let fc = f(c);
  let fd = f(d);
  for (let i = 0; i < 200 && hi - lo > tolerance; i += 1) {
    if (fc > fd) {
      hi = d;
      d = c;
      fd = fc;
      c = hi - INVERSE_PHI * (hi - lo);
      fc = f(c);
    } else {
      lo = c;
      c = d;
      fc = fd;
      d = lo + INVERSE_PHI * (hi - lo);
      fd = f(d);
    }
  }
  return (lo + hi) / 2;
}

/**
 * The largest of `values` (sampled at `theta`, ascending) refined with f, the function they
 * sample: { value, theta }. The grid's own sample stands where refining finds nothing larger.
 * @param {readonly number[]} theta
 * @param {ArrayLike<number>} values
 * @param {(theta: number) => number} f
 */
export function refinedMax(theta, values, f) {
  let at = 0;
  for (let i = 1; i < values.length; i += 1) if (values[i] > values[at]) at = i;
  const t = goldenMax(f, theta[Math.max(0, at - 1)], theta[Math.min(theta.length - 1, at + 1)]);
  const v = f(t);
  return v > values[at] ? { value: v, theta: t } : { value: values[at], theta: theta[at] };
}
