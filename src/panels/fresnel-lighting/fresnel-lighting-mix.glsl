// The lecture's model: the coat reflects F, the diffuse layer the rest, k = mix(kd, ks, F),
// with one F at the view angle N·V, from air (1.0) into the coat (n).
vec3 kExact = mix(kd, ks, fresnelExact(dot(N, V), 1.0, n));
vec3 kSchlick = mix(kd, ks, fresnelSchlick(dot(N, V), 1.0, n));
vec3 kConstant = mix(kd, ks, w); // a fixed "ks slider": the same weight at every angle
// Beyond the lecture, a layered coat (Weidlich & Wilkie 2007): the sunlight enters the coat at
// its own angle (1 − F(N·L)), sky light loses re, what the base sends back leaves at the view
// angle (1 − F(N·V)) and spreads into a wider cone (1/n²), and the coat's underside returns ri
// of it to the base, again and again: 1/(1 − albedo·ri).
float fV = fresnelExact(dot(N, V), 1.0, n);
vec3 kLayered = fV * ks + (1.0 - fV) / (n * n)
  * albedo * ((1.0 - fresnelExact(cosL, 1.0, n)) * sun + (1.0 - re) * sky) / (1.0 - albedo * ri);
