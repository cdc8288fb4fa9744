// lighting.glsl - the lab's lighting model: one source, two faces.
//
// This file is compiled twice:
//   * as GLSL ES 3.00, prepended (after lighting_api.glsl, which declares the constants, structs
//     and prototypes) to lit.vert and lit.frag by lab/render/shader.cpp;
//   * as C++20 with GLM, included by lab/core/lighting/lighting.cpp inside namespace lab::glsl,
//     where it feeds the polar plots, `lab plot` and the tests.
// The CPU-GPU parity test (tests/gpu_parity_test.cpp) renders probes through the real
// shaders and checks them against the C++ build of this very file.
//
// Keep to the subset both languages share: structs, scalar/vector value parameters,
// return values (no in/out/inout qualifiers), float literals with an `f` suffix, GLM
// names that GLSL also has, no overloading, no struct constructors, no recursion.
//
// Everything is in camera (eye) space; N, L, V are unit vectors, V = normalize(-p).
// The contract, with every formula, is the README's "The lighting model" section.

//----------------------------------------------------------------------------------------
// Light falloff
//----------------------------------------------------------------------------------------

// min(1, 1/(c0 + c1 d + c2 d^2)). OpenGL 1.x fixed-function attenuation, clamped so a light
// never brightens past its nominal colour; a zero denominator is the limit, 1.
float attenuation(vec3 c, float d) {
    float denom = c.x + c.y * d + c.z * d * d;
    return denom > 1.0f ? 1.0f / denom : 1.0f;
}

// (cos gamma)^exponent inside the cone, 0 outside; cos gamma = (-L).S. OpenGL 1.x spot light.
float spotFactor(vec3 L, vec3 S, float cosCutoff, float exponent) {
    float cosGamma = dot(-L, S);
    if (cosGamma < cosCutoff) {
        return 0.0f;
    }
    // pow(0, 0) is undefined in GLSL: exponent 0 means "no falloff" inside the cone.
    return exponent > 0.0f ? pow(max(cosGamma, 0.0f), exponent) : 1.0f;
}

//----------------------------------------------------------------------------------------
// Specular lobes
//----------------------------------------------------------------------------------------

// R = 2(N.L)N - L, the mirror direction of L about N. Phong 1975.
vec3 reflectionVector(vec3 N, vec3 L) {
    return 2.0f * dot(N, L) * N - L;
}

// H = normalize(L + V). Blinn 1977.
vec3 halfVector(vec3 L, vec3 V) {
    return normalize(L + V);
}

// H and the dot products N.H, N.V, N.L, V.H (not clamped).
Dots dotsOf(vec3 N, vec3 L, vec3 V) {
    Dots d;
    d.H = halfVector(L, V);
    d.NoH = dot(N, d.H);
    d.NoV = dot(N, V);
    d.NoL = dot(N, L);
    d.VoH = dot(V, d.H);
    return d;
}

// max(0, R.V)^n. Phong 1975.
float phongSpecular(vec3 N, vec3 L, vec3 V, float shininess) {
    return pow(max(dot(reflectionVector(N, L), V), 0.0f), shininess);
}

// max(0, N.H)^n. Blinn 1977.
float blinnPhongSpecular(vec3 N, vec3 L, vec3 V, float shininess) {
    return pow(max(dot(N, halfVector(L, V)), 0.0f), shininess);
}

//----------------------------------------------------------------------------------------
// Cook-Torrance microfacet terms (c = N.H, m = roughness)
//----------------------------------------------------------------------------------------

// exp((c^2 - 1)/(c^2 m^2)) / (pi m^2 c^4). Beckmann 1963. Below c = 10^-4 the value is 0 in
// float for every accepted m (at most 10: exp(-10^6)); computing it there would divide 0 by a
// c^4 that underflows to 0.
float distributionBeckmann(float NoH, float m) {
    if (NoH <= 1e-4f) {
        return 0.0f;
    }
    float c2 = NoH * NoH;
    float m2 = m * m;
    return exp((c2 - 1.0f) / (c2 * m2)) / (PI * m2 * c2 * c2);
}

// exp(-(acos(c)/m)^2) / (pi m^2). Cook & Torrance 1982 (Gaussian facet slopes).
float distributionGaussian(float NoH, float m) {
    if (NoH <= 0.0f) {
        return 0.0f;
    }
    float alpha = acos(min(NoH, 1.0f));
    float t = alpha / m;
    return exp(-(t * t)) / (PI * m * m);
}

// m^2 / (pi (c^2(m^2 - 1) + 1)^2). Walter et al. 2007 (GGX).
float distributionGGX(float NoH, float m) {
    if (NoH <= 0.0f) {
        return 0.0f;
    }
    float m2 = m * m;
    float k = NoH * NoH * (m2 - 1.0f) + 1.0f;
    return m2 / (PI * k * k);
}

// F0 = ((ior - 1)/(ior + 1))^2, reflectance at normal incidence from air.
float fresnelF0(float ior) {
    float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

// F0 + (1 - F0)(1 - V.H)^5. Schlick 1994.
float fresnelSchlick(float VoH, float F0) {
    float k = 1.0f - clamp(VoH, 0.0f, 1.0f);
    float k2 = k * k;
    return F0 + (1.0f - F0) * k2 * k2 * k;
}

// (Rs + Rp)/2, the unpolarized Fresnel reflectance of a dielectric seen from air, with
// cos thetai = V.H and thetat from Snell's law; 1 under total internal reflection (ior < 1).
// Cook & Torrance 1982.
float fresnelDielectric(float VoH, float ior) {
    float cosI = clamp(VoH, 0.0f, 1.0f);
    float sinT2 = (1.0f - cosI * cosI) / (ior * ior);
    if (sinT2 >= 1.0f) {
        return 1.0f;
    }
    float cosT = sqrt(1.0f - sinT2);
    float rs = (cosI - ior * cosT) / (cosI + ior * cosT);
    float rp = (cosT - ior * cosI) / (cosT + ior * cosI);
    return 0.5f * (rs * rs + rp * rp);
}

// min(1, 2(N.H)(N.V)/(V.H), 2(N.H)(N.L)/(V.H)), masking and shadowing of V-shaped grooves.
// Cook & Torrance 1982 (after Torrance & Sparrow 1967, Blinn 1977). Clamped at 0 where an
// interpolated normal faces away from the viewer.
float geometryCookTorrance(float NoH, float NoV, float NoL, float VoH) {
    float k = 2.0f * NoH / max(VoH, 1e-4f);
    return clamp(min(k * NoV, k * NoL), 0.0f, 1.0f);
}

float distributionTerm(float NoH, Brdf b) {
    if (b.distribution == DISTRIBUTION_GAUSSIAN) {
        return distributionGaussian(NoH, b.roughness);
    }
    if (b.distribution == DISTRIBUTION_GGX) {
        return distributionGGX(NoH, b.roughness);
    }
    return distributionBeckmann(NoH, b.roughness);
}

float fresnelTerm(float VoH, Brdf b) {
    if (b.fresnel == FRESNEL_FULL) {
        return fresnelDielectric(VoH, b.ior);
    }
    return fresnelSchlick(VoH, fresnelF0(b.ior));
}

float geometryTerm(float NoH, float NoV, float NoL, float VoH, Brdf b) {
    return b.geometry ? geometryCookTorrance(NoH, NoV, NoL, VoH) : 1.0f;
}

// 4 max(N.V, 1e-4): the textbook's 4 (N.L)(N.V) after its N.L has cancelled against the cosine
// of the incoming light (see below); the floor keeps a normal facing away from V finite.
float cookTorranceDenominator(float NoV) {
    return 4.0f * max(NoV, 1e-4f);
}

// D.F.G / (4 max(N.V, 1e-4)): the microfacet BRDF D F G / (4 (N.L)(N.V)) times N.L.
// Cook & Torrance 1982.
float cookTorranceSpecular(vec3 N, vec3 L, vec3 V, Brdf b) {
    Dots d = dotsOf(N, L, V);
    float D = distributionTerm(d.NoH, b);
    float F = fresnelTerm(d.VoH, b);
    float G = geometryTerm(d.NoH, d.NoV, d.NoL, d.VoH, b);
    return D * F * G / cookTorranceDenominator(d.NoV);
}

// The specular factor S for the chosen BRDF; 0 wherever N.L <= 0.
float specularFactor(vec3 N, vec3 L, vec3 V, float shininess, Brdf b) {
    if (dot(N, L) <= 0.0f) {
        return 0.0f;
    }
    if (b.model == BRDF_BLINN_PHONG) {
        return blinnPhongSpecular(N, L, V, shininess);
    }
    if (b.model == BRDF_COOK_TORRANCE) {
        return cookTorranceSpecular(N, L, V, b);
    }
    return phongSpecular(N, L, V, shininess);
}

//----------------------------------------------------------------------------------------
// The whole model
//----------------------------------------------------------------------------------------

// Unit vector from the surface point p towards light l; 0 for a light exactly at p (no direction:
// it lights nothing there but its ambient term).
vec3 lightVector(Light l, vec3 p) {
    if (l.type == LIGHT_DIRECTIONAL) {
        return -l.direction;
    }
    vec3 d = l.position - p;
    return dot(d, d) > 1e-30f ? normalize(d) : vec3(0.0f);
}

// d, the distance from p to light l; 0 for a directional light (it has none).
float lightDistance(Light l, vec3 p) {
    return l.type == LIGHT_DIRECTIONAL ? 0.0f : length(l.position - p);
}

// Att(d) of light l at p; 1 for a directional light.
float distanceAttenuation(Light l, vec3 p) {
    return l.type == LIGHT_DIRECTIONAL ? 1.0f : attenuation(l.attenuation, lightDistance(l, p));
}

// The spot factor of light l for the unit vector L towards it; 1 for a light that is not a spot.
float spotTerm(Light l, vec3 L) {
    return l.type == LIGHT_SPOT ? spotFactor(L, l.direction, l.cosCutoff, l.exponent) : 1.0f;
}

// Att_i: distance attenuation times the spot factor; 1 for a directional light.
float lightAttenuation(Light l, vec3 p, vec3 L) {
    return distanceAttenuation(l, p) * spotTerm(l, L);
}

// Light l's terms of the sum below, Ia_i*Ka + Att_i (Id_i*Kd max(0, N.L_i) + Is_i*Ks S_i),
// each on its own and 0 where its switch is off. The shaders add them up; the GUI's probe shows
// them one by one. Phong 1975, with the OpenGL 1.x light model.
LightTerms lightContribution(Material m, Brdf b, Terms t, Light l, vec3 p, vec3 N, vec3 V) {
    LightTerms c;
    c.L = lightVector(l, p);
    c.attenuation = lightAttenuation(l, p, c.L);
    c.NoL = dot(N, c.L);
    c.specularFactor = specularFactor(N, c.L, V, m.shininess, b);
    c.ambient = t.ambient ? l.ambient * m.ambient : vec3(0.0f);
    c.diffuse = t.diffuse ? c.attenuation * l.diffuse * m.diffuse * max(c.NoL, 0.0f) : vec3(0.0f);
    c.specular = t.specular ? c.attenuation * l.specular * m.specular * c.specularFactor : vec3(0.0f);
    return c;
}

// colour = Ke + Ia*Ka + sum_i [ Ia_i*Ka + Att_i (Id_i*Kd max(0, N.L_i) + Is_i*Ks S_i) ],
// clamped to [0, 1]. Phong 1975, with the OpenGL 1.x light model.
vec3 shade(Material m, Brdf b, Terms t, vec3 ambientLight, Light lights[MAX_LIGHTS],
           int lightCount, vec3 p, vec3 N) {
    vec3 V = viewVector(p);
    vec3 color = vec3(0.0f);
    if (t.emissive) {
        color += m.emissive;
    }
    if (t.ambient) {
        color += ambientLight * m.ambient;
    }
    for (int i = 0; i < lightCount; ++i) {
        LightTerms c = lightContribution(m, b, t, lights[i], p, N, V);
        color += c.ambient;
        color += c.diffuse;
        color += c.specular;
    }
    return clamp(color, 0.0f, 1.0f);
}

// V, the unit vector from p towards the eye (at the origin of eye space); a point at the eye looks
// along -z.
vec3 viewVector(vec3 p) {
    return dot(p, p) > 1e-30f ? normalize(-p) : vec3(0.0f, 0.0f, 1.0f);
}

//----------------------------------------------------------------------------------------
// The factors, one at a time (the factor views)
//----------------------------------------------------------------------------------------

// One factor of light l's term at p, computed by the very functions shade() multiplies together:
// max(0, N.L), max(0, N.V), max(0, R.V), max(0, N.H), D, F, G, the Cook-Torrance denominator,
// Att(d), the spot factor and d. So with one light and N.L > 0, Cook-Torrance's specular term is
// D F G / denominator * Ks Is * attenuation * spot, and Phong's is R.V^n * Ks Is * attenuation * spot.
float equationFactor(int factor, Brdf b, Light l, vec3 p, vec3 N, vec3 V) {
    vec3 L = lightVector(l, p);
    Dots d = dotsOf(N, L, V);
    if (factor == FACTOR_N_DOT_L) {
        return max(d.NoL, 0.0f);
    }
    if (factor == FACTOR_N_DOT_V) {
        return max(d.NoV, 0.0f);
    }
    if (factor == FACTOR_R_DOT_V) {
        return max(dot(reflectionVector(N, L), V), 0.0f);
    }
    if (factor == FACTOR_N_DOT_H) {
        return max(d.NoH, 0.0f);
    }
    if (factor == FACTOR_D) {
        return distributionTerm(d.NoH, b);
    }
    if (factor == FACTOR_F) {
        return fresnelTerm(d.VoH, b);
    }
    if (factor == FACTOR_G) {
        return geometryTerm(d.NoH, d.NoV, d.NoL, d.VoH, b);
    }
    if (factor == FACTOR_DENOMINATOR) {
        return cookTorranceDenominator(d.NoV);
    }
    if (factor == FACTOR_ATTENUATION) {
        return distanceAttenuation(l, p);
    }
    if (factor == FACTOR_SPOT) {
        return spotTerm(l, L);
    }
    return lightDistance(l, p);
}
