// lighting_api.glsl - the lighting model's constants, structs and function prototypes.
//
// Valid GLSL ES 3.00 and valid C++20 with GLM, like lighting.glsl, which holds the definitions.
// C++ includes this file from lab/core/lighting/lighting.h (any number of translation units may), and
// lighting.glsl from lab/core/lighting/lighting.cpp only. The shaders get both, this one first.
// A definition that drifts from its prototype fails to link in both languages.

const float PI = 3.14159265358979f;
const int MAX_LIGHTS = 8;

// The values of Light.type, Brdf.model, Brdf.distribution and Brdf.fresnel, one line each: the
// order of preset.h's enums (lab/core/lighting/lighting.cpp checks that they agree).
const int LIGHT_POINT = 0, LIGHT_DIRECTIONAL = 1, LIGHT_SPOT = 2;
const int BRDF_PHONG = 0, BRDF_BLINN_PHONG = 1, BRDF_COOK_TORRANCE = 2;
const int DISTRIBUTION_BECKMANN = 0, DISTRIBUTION_GAUSSIAN = 1, DISTRIBUTION_GGX = 2;
const int FRESNEL_SCHLICK = 0, FRESNEL_FULL = 1;
// The factors equationFactor() gives, in view_mode.h's order of the factor views (from NdotL).
const int FACTOR_N_DOT_L = 0, FACTOR_N_DOT_V = 1, FACTOR_R_DOT_V = 2, FACTOR_N_DOT_H = 3, FACTOR_D = 4,
          FACTOR_F = 5, FACTOR_G = 6, FACTOR_DENOMINATOR = 7, FACTOR_ATTENUATION = 8, FACTOR_SPOT = 9,
          FACTOR_DISTANCE = 10;

struct Material {
    vec3 emissive;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float shininess;
};

// `brdf` picks the specular lobe; the other fields are Cook-Torrance's.
struct Brdf {
    int model;
    int distribution;
    int fresnel;
    bool geometry;
    float roughness;
    float ior;
};

struct Terms {
    bool emissive;
    bool ambient;
    bool diffuse;
    bool specular;
};

// A light already in eye space: position transformed by the view matrix, direction by its
// upper 3x3 and normalized. Only enabled lights are packed.
struct Light {
    int type;
    vec3 position;
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    vec3 attenuation; // c0, c1, c2
    float cosCutoff;
    float exponent;
};

// The half vector and the dot products of N, L, V and H that the lobes read.
struct Dots {
    vec3 H;
    float NoH;
    float NoV;
    float NoL;
    float VoH;
};

// One light's share of the colour at a point, term by term, with what the terms come from.
// A term whose switch (Terms) is off is 0.
struct LightTerms {
    vec3 L;               // unit vector towards the light
    float attenuation;    // Att_i, the spot factor included
    float NoL;            // N.L, not clamped
    float specularFactor; // S_i, 0 wherever N.L <= 0
    vec3 ambient;         // Ia_i*Ka
    vec3 diffuse;         // Att_i Id_i*Kd max(0, N.L)
    vec3 specular;        // Att_i Is_i*Ks S_i
};

// Light falloff
float attenuation(vec3 c, float d);
float spotFactor(vec3 L, vec3 S, float cosCutoff, float exponent);

// Specular lobes
vec3 reflectionVector(vec3 N, vec3 L);
vec3 halfVector(vec3 L, vec3 V);
Dots dotsOf(vec3 N, vec3 L, vec3 V);
float phongSpecular(vec3 N, vec3 L, vec3 V, float shininess);
float blinnPhongSpecular(vec3 N, vec3 L, vec3 V, float shininess);

// Cook-Torrance terms
float distributionBeckmann(float NoH, float m);
float distributionGaussian(float NoH, float m);
float distributionGGX(float NoH, float m);
float fresnelF0(float ior);
float fresnelSchlick(float VoH, float F0);
float fresnelDielectric(float VoH, float ior);
float geometryCookTorrance(float NoH, float NoV, float NoL, float VoH);
float distributionTerm(float NoH, Brdf b);
float fresnelTerm(float VoH, Brdf b);
float geometryTerm(float NoH, float NoV, float NoL, float VoH, Brdf b);
float cookTorranceDenominator(float NoV);
float cookTorranceSpecular(vec3 N, vec3 L, vec3 V, Brdf b);
float specularFactor(vec3 N, vec3 L, vec3 V, float shininess, Brdf b);

// The whole model
vec3 lightVector(Light l, vec3 p);
float lightDistance(Light l, vec3 p);
float distanceAttenuation(Light l, vec3 p);
float spotTerm(Light l, vec3 L);
float lightAttenuation(Light l, vec3 p, vec3 L);
LightTerms lightContribution(Material m, Brdf b, Terms t, Light l, vec3 p, vec3 N, vec3 V);
vec3 shade(Material m, Brdf b, Terms t, vec3 ambientLight, Light lights[MAX_LIGHTS],
           int lightCount, vec3 p, vec3 N);
vec3 viewVector(vec3 p);
float equationFactor(int factor, Brdf b, Light l, vec3 p, vec3 N, vec3 V);
