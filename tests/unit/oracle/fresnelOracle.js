// High-precision reference for the Fresnel equations, written from the physics (Hecht, Optics
// §4.6) with decimal.js at 50 significant digits. It shares no code with src/optics, so an error
// in the float64 module cannot be reproduced here by construction.
import Decimal from 'decimal.js';

/** Private decimal.js constructor: 50 digits, round-half-even, so global settings cannot leak in. */
export const D = Decimal.clone({ precision: 50, rounding: Decimal.ROUND_HALF_EVEN });

const ZERO = new D(0);
const ONE = new D(1);

/**
 * The exact value of a float64 as a Decimal.
 * Why not `new D(x)`: decimal.js parses String(x), the shortest round-trip form ("0.1"), which is
 * NOT the double's value (0.1000000000000000055511151231257827...). Instead the IEEE-754 bits are
 * split into an integer significand M and exponent e (x = M·2^e), and for e < 0 the identity
 * M·2^e = (M·5^−e)·10^e gives a finite decimal string that the Decimal constructor stores
 * digit-for-digit (the constructor never rounds to `precision`; only arithmetic does).
 */
export function exactDecimal(x) {
  if (typeof x !== 'number' || !Number.isFinite(x)) throw new RangeError(`not a finite double: ${x}`);
  if (x === 0) return ZERO;
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const bits = view.getBigUint64(0);
  const sign = bits >> 63n ? '-' : '';
  const biased = Number((bits >> 52n) & 0x7ffn);
  const fraction = bits & 0xfffffffffffffn;
  // Normal numbers carry the implicit leading 1; subnormals use exponent 1 − 1075 without it.
  const M = biased === 0 ? fraction : fraction | (1n << 52n);
  const e = (biased === 0 ? 1 : biased) - 1075;
  if (e >= 0) return new D(sign + (M << BigInt(e)).toString());
  return new D(`${sign}${(M * 5n ** BigInt(-e)).toString()}e${e}`);
}

/** Accepts a double (converted exactly) or an existing Decimal. */
function dec(x) {
  return x instanceof D ? x : exactDecimal(x);
}

/**
 * Power reflectances rs², rp² of a dielectric interface, light going from nI into nT.
 * Snell: sin²θt = m²(1 − cos²θi) with m = nI/nT; sin²θt ≥ 1 is total internal reflection.
 */
export function dielectricSP(cosThetaI, nI, nT) {
  const ci = dec(cosThetaI);
  const n1 = dec(nI);
  const n2 = dec(nT);
  if (n1.eq(n2)) return { s: ZERO, p: ZERO }; // no interface, nothing reflects
  const m = n1.div(n2);
  const sin2t = m.times(m).times(ONE.minus(ci.times(ci)));
  if (sin2t.gte(ONE)) return { s: ONE, p: ONE };
  const ct = ONE.minus(sin2t).sqrt();
  const rs = n1.times(ci).minus(n2.times(ct)).div(n1.times(ci).plus(n2.times(ct)));
  const rp = n2.times(ci).minus(n1.times(ct)).div(n2.times(ci).plus(n1.times(ct)));
  return { s: rs.times(rs), p: rp.times(rp) };
}

/** Unpolarized dielectric reflectance, the mean of the s and p power reflectances. */
export function dielectricR(cosThetaI, nI, nT) {
  const { s, p } = dielectricSP(cosThetaI, nI, nT);
  return s.plus(p).div(2);
}

const PI = D.acos(-1);

/** cos θ for θ in degrees (a double, taken as the decimal it is), as a Decimal. */
export function cosOfDegrees(thetaDeg) {
  return D.cos(dec(thetaDeg).times(PI).div(180));
}

/** Brewster angle in degrees, tan θB = nT/nI (Hecht, Optics §8.6.1). */
export function brewsterDegrees(nI, nT) {
  return D.atan(dec(nT).div(dec(nI))).times(180).div(PI);
}

/** Critical angle in degrees, sin θc = nT/nI for nI > nT (Hecht, Optics §4.7). */
export function criticalDegrees(nI, nT) {
  return D.asin(dec(nT).div(dec(nI))).times(180).div(PI);
}

// ---- A minimal complex type on Decimal, just enough for the conductor case. ----

export class Complex {
  constructor(re, im = ZERO) {
    this.re = dec(re);
    this.im = dec(im);
  }

  plus(z) {
    return new Complex(this.re.plus(z.re), this.im.plus(z.im));
  }

  minus(z) {
    return new Complex(this.re.minus(z.re), this.im.minus(z.im));
  }

  times(z) {
    return new Complex(
      this.re.times(z.re).minus(this.im.times(z.im)),
      this.re.times(z.im).plus(this.im.times(z.re)),
    );
  }

  div(z) {
    const d = z.abs2();
    return new Complex(
      this.re.times(z.re).plus(this.im.times(z.im)).div(d),
      this.im.times(z.re).minus(this.re.times(z.im)).div(d),
    );
  }

  /** |z|². */
  abs2() {
    return this.re.times(this.re).plus(this.im.times(this.im));
  }

  /**
   * Principal square root (Re ≥ 0; Im ≥ 0 on the negative real axis). The larger of
   * |re|, |im| comes from sqrt((|z| + |x|)/2), which does not cancel; the other is y/(2·that).
   */
  sqrt() {
    const x = this.re;
    const y = this.im;
    if (x.isZero() && y.isZero()) return new Complex(ZERO);
    const t = this.abs2().sqrt().plus(x.abs()).div(2).sqrt();
    if (!x.isNegative()) return new Complex(t, y.div(t.times(2)));
    return new Complex(y.abs().div(t.times(2)), y.isNegative() ? t.neg() : t);
  }
}

/**
 * s and p power reflectances from air (index 1) into a conductor with complex index η = n + ik:
 * cosθt = sqrt(1 − sin²θi/η²) (principal root), rs = (ci − η ct)/(ci + η ct),
 * rp = (η ci − ct)/(η ci + ct). With k ≥ 0, 1 − sin²/η² lies in the upper half plane, so the
 * principal root makes η·ct the decaying (Im ≥ 0) wave and |rs|, |rp| ≤ 1.
 */
export function conductorSP(cosThetaI, n, k) {
  const ci = new Complex(dec(cosThetaI));
  const eta = new Complex(dec(n), dec(k));
  const sin2 = new Complex(ONE.minus(ci.re.times(ci.re)));
  const ct = new Complex(ONE).minus(sin2.div(eta.times(eta))).sqrt();
  const etaCt = eta.times(ct);
  const etaCi = eta.times(ci);
  const rs = ci.minus(etaCt).div(ci.plus(etaCt));
  const rp = etaCi.minus(ct).div(etaCi.plus(ct));
  return { s: rs.abs2(), p: rp.abs2() };
}

/** Unpolarized conductor reflectance, (|rs|² + |rp|²)/2. */
export function conductorR(cosThetaI, n, k) {
  const { s, p } = conductorSP(cosThetaI, n, k);
  return s.plus(p).div(2);
}

/** |float64 result − oracle| as a double, with the float64 result converted exactly. */
export function absError(value, oracle) {
  return exactDecimal(value).minus(oracle).abs().toNumber();
}
