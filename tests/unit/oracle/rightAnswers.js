// The right answers to some homework questions, worked out from the physics with none of the lab's
// code (for tests whose subject is what is done with right and wrong answers, such as a class's
// gradebook): a number in the unit the question asks for, or the id of the option that holds.
// Hecht, Optics (5th ed.), §4.4 (Snell), §4.6.2 (Fresnel equations, Brewster's angle).
const DEG = Math.PI / 180;

/** Unpolarized R at θ (degrees) from n_i into n_t, plain float64; 1 past the critical angle. */
export function fresnelR(thetaDeg, nI, nT) {
  const ci = Math.cos(thetaDeg * DEG);
  const st = (nI / nT) * Math.sin(thetaDeg * DEG);
  if (st >= 1) return 1;
  const ct = Math.sqrt(1 - st * st);
  const rs = (nI * ci - nT * ct) / (nI * ci + nT * ct);
  const rp = (nT * ci - nI * ct) / (nT * ci + nI * ct);
  return (rs * rs + rp * rp) / 2;
}

const RIGHT = {
  'exact-r': (p) => fresnelR(p.theta, 1, p.nT),
  'r0-value': (p) => ((p.nT - 1) / (p.nT + 1)) ** 2,
  'snell-angle': (p) => Math.asin(Math.sin(p.theta * DEG) / p.nT) / DEG,
  'brewster-predict': (p) => Math.atan(p.nT) / DEG,
  // A metal's reflectance rises towards 1 in every channel at grazing incidence, so its colour
  // fades towards white (the test of this against the 50-digit oracle is in homeworkGraded.test.js).
  'metal-grazing': () => 'towards-white',
};

/** The right answer to question `id` for parameters p; throws for a question not worked out here. */
export function rightAnswer(id, p) {
  if (!Object.hasOwn(RIGHT, id)) throw new Error(`no right answer worked out for ${id}`);
  return RIGHT[id](p);
}
