// The coat reflects F, the diffuse layer the rest (lecture: k = mix(kd, ks, F)).
// F at the view angle N·V, from air (1.0) into the coat (n).
vec3 kExact = mix(kd, ks, fresnelExact(dot(N, V), 1.0, n));
vec3 kSchlick = mix(kd, ks, fresnelSchlick(dot(N, V), 1.0, n));
vec3 kConstant = mix(kd, ks, w); // a fixed "ks slider": the same weight at every angle
