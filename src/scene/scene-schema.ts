import { z } from 'zod';
import type { Camera, Light, Material, RenderSettings, Scene, SceneObject } from './scene.ts';
import { MESH_ASSET_NAMES } from './mesh-assets.ts';
import { alsoWhenFieldsFail, asRefinement, cameraHasDirection, idsAreUnique, meshOnlyOnMeshes, primaryRaysWithinLimit } from './scene-rules.ts';
import { LIMITS } from './scene-limits.ts';
import { numberIn, pair, triple, wholeNumberIn } from './scene-schema-parts.ts';
import { describeIssue, issuesOf, withReason } from './scene-issues.ts';
import type { Issue } from '../util/issue.ts';
import { jsonIssue } from '../util/json-error.ts';

/**
 * The scene file's schema (spec §1): every field but the ids (and `version`) has a default,
 * unknown fields are rejected, and every problem becomes one `path: reason` line.
 * docs/scene-format.md explains each field to teachers; docs/schema/scene.schema.json is
 * generated from this file (`npm run schema`).
 */

const coordinates = () => triple(numberIn(LIMITS.coordinate), 'numbers');
const color = () => triple(numberIn(LIMITS.channel), 'numbers between 0 and 1');
const coefficient = () => numberIn(LIMITS.coefficient);
const id = () => z.string().min(LIMITS.idLength[0]).max(LIMITS.idLength[1]);
const nameText = () => z.string().max(LIMITS.nameLength[1]);
/** A plain name (English, as older files have it), or one per language like a level text: `{ "en": "Red ball", "nl": "Rode bal" }`. */
const name = () =>
  z
    .union([nameText(), z.strictObject({ en: nameText(), nl: nameText().optional() })], {
      error: (issue) => withReason(issue, { code: 'notNameText', most: LIMITS.nameLength[1] }),
    })
    .optional()
    .describe('A friendly name for the UI: a text, or { "en": …, "nl": … } with one per language.');

const cameraSchema = z
  .strictObject({
    position: coordinates().default([0, 1, 5]),
    target: coordinates().default([0, 0.5, 0]).describe('The point the camera looks at; up is +Y.'),
    fov: numberIn(LIMITS.fov).default(45).describe('Vertical field of view in degrees.'),
    pixels: pair(wholeNumberIn(LIMITS.pixels), 'whole numbers').default([8, 6]).describe('Columns and rows of the small screen whose rays are drawn in 3D.'),
    screenDistance: numberIn(LIMITS.screenDistance).default(1).describe('Metres from the eye to the drawn screen (drawing only).'),
    aperture: numberIn(LIMITS.aperture).default(0).describe('Lens radius in metres; 0 is a pinhole (everything sharp).'),
    focusDistance: numberIn(LIMITS.focusDistance)
      .optional()
      .describe('Metres to the plane in focus, along the view direction; left out: the distance to target.'),
    lensSamples: wholeNumberIn(LIMITS.lensSamples).default(1).describe('n: n×n points on the lens per pixel sample (ignored while aperture is 0).'),
  })
  .superRefine(asRefinement(cameraHasDirection), alsoWhenFieldsFail)
  .describe('The ray tracer camera and its small screen of visualized pixels.');

const settingsSchema = z
  .strictObject({
    shadows: z.boolean().default(true),
    maxDepth: wholeNumberIn(LIMITS.maxDepth).default(3).describe('Deepest reflection/refraction bounce; primary rays are depth 0.'),
    background: color().default([0.7, 0.7, 0.7]).describe('The colour of a ray that hits nothing.'),
    supersampling: wholeNumberIn(LIMITS.supersampling).default(1).describe('s: s×s samples per pixel.'),
    samplePattern: z.enum(['grid', 'jittered', 'random']).default('grid'),
    imageSize: pair(wholeNumberIn(LIMITS.imageSize), 'whole numbers').default([512, 384]).describe('Width and height of the full rendered image.'),
    dithering: z.boolean().default(false).describe('Ordered dithering before 8-bit quantization.'),
    encoding: z
      .enum(['none', 'linear', 'srgb'])
      .default('none')
      .describe('How colours become 8-bit values: none (c·255, no gamma), linear (light in equal steps) or srgb (sRGB-encoded light).'),
    lightTypes: z
      .strictObject({
        point: z.boolean().default(true),
        spot: z.boolean().default(true),
        area: z.boolean().default(true),
      })
      .prefault({})
      .describe('A switch per light type; a switched-off type lights nothing.'),
    timeSamples: wholeNumberIn(LIMITS.timeSamples).default(1).describe('k: times in the open shutter per pixel sample (motion blur).'),
    timePattern: z
      .enum(['grid', 'jittered', 'random'])
      .default('jittered')
      .describe('Where the k times go: the same moments (i + ½)/k for every pixel, (i + ξ)/k per pixel sample, or k uniform ones.'),
    integrator: z.enum(['whitted', 'path']).default('whitted').describe("Which estimator renders the scene: Whitted's recursive tracer or a path tracer."),
    pathSamples: wholeNumberIn(LIMITS.pathSamples).default(16).describe('N: random paths per pixel (path mode).'),
    pixelSampling: z
      .enum(['stratified', 'independent'])
      .default('stratified')
      .describe("Where in the pixel each path starts (path mode): stratified, a pixel's paths spread evenly over it, or independent uniform random points."),
    bounceSampling: z.enum(['cosine', 'uniform']).default('cosine').describe('How a diffuse bounce picks its direction (path mode).'),
    lightSampling: z.boolean().default(true).describe('At each diffuse vertex, also a shadow ray to a point on each light (path mode).'),
    russianRoulette: z.boolean().default(false).describe('End paths at random, survivors weighted up, as well as at maxDepth (path mode).'),
    exposure: numberIn(LIMITS.exposure).default(0).describe('Stops: the picture times 2^exposure before display (path mode).'),
  })
  .describe('How the image is rendered.');

const materialSchema = z
  .strictObject({
    color: color().default([1, 1, 1]),
    ambient: coefficient().default(0.2),
    diffuse: coefficient().default(1),
    specular: coefficient().default(0).describe('Highlight strength, and for an opaque object also how much it mirrors.'),
    shininess: numberIn(LIMITS.shininess).default(32).describe('Phong exponent n: higher is a smaller highlight.'),
    transparent: z.boolean().default(false),
    refractiveIndex: numberIn(LIMITS.refractiveIndex).default(1.5).describe('η, used when transparent.'),
    roughness: numberIn(LIMITS.roughness).default(0).describe('Spread of reflected (and refracted) rays; 0 is a perfect mirror or clear glass.'),
    glossySamples: wholeNumberIn(LIMITS.glossySamples).default(3).describe('m: m×m reflected (refracted) rays per hit when roughness > 0.'),
  })
  .describe('Phong material (spec §2).');

export const sceneObjectSchema = z
  .strictObject({
    id: id().describe('Unique among all objects and lights.'),
    name: name(),
    shape: z.enum(['sphere', 'box', 'cylinder', 'plane', 'mesh']).default('sphere'),
    mesh: z.enum(MESH_ASSET_NAMES).optional().describe('The model from assets/models; only and always with shape "mesh".'),
    position: coordinates().default([0, 0, 0]),
    rotation: coordinates().default([0, 0, 0]).describe('Euler angles XYZ in degrees.'),
    scale: triple(numberIn(LIMITS.scale), 'positive numbers').default([1, 1, 1]),
    velocity: triple(numberIn(LIMITS.velocity), 'numbers').default([0, 0, 0]).describe('Metres the object moves while the shutter is open (motion blur).'),
    material: materialSchema.prefault({}),
  })
  .superRefine(asRefinement(meshOnlyOnMeshes), alsoWhenFieldsFail)
  .describe('A unit shape placed by position, rotation and scale.');

const lightFields = {
  id: id().describe('Unique among all objects and lights.'),
  name: name(),
  // Above the origin rather than at it, so a new light is not buried inside the objects.
  position: coordinates().default([0, 3, 0]),
  color: color().default([1, 1, 1]),
  intensity: numberIn(LIMITS.intensity).default(1),
  ambient: coefficient().default(0.1),
  diffuse: coefficient().default(1),
  specular: coefficient().default(1),
  distanceAttenuation: z.boolean().default(false).describe('Dim with distance d by 1 / (0.04 + 0.1·d + 0.06·d²).'),
};

/** Spot and area lights point along their local −Y: with no rotation, straight down. */
const aimedLightFields = {
  rotation: coordinates().default([0, 0, 0]).describe('Euler angles XYZ in degrees; unrotated, the light shines down.'),
  angleAttenuation: numberIn(LIMITS.angleAttenuation).default(1).describe('p in cos(α)^p.'),
};

export const lightSchema = z
  .discriminatedUnion('type', [
    z.strictObject({
      // The one type that may be left out, so that every field has a default (spec §1).
      type: z.literal('point').optional().default('point'),
      ...lightFields,
    }),
    z.strictObject({
      type: z.literal('spot'),
      ...lightFields,
      ...aimedLightFields,
      spotAngle: numberIn(LIMITS.spotAngle).default(45).describe('Full cone angle in degrees.'),
    }),
    z.strictObject({
      type: z.literal('area'),
      ...lightFields,
      ...aimedLightFields,
      size: pair(numberIn(LIMITS.areaSize), 'numbers').default([1, 1]).describe('Width (local X) and depth (local Z) in metres.'),
      samples: wholeNumberIn(LIMITS.areaSamples).default(3).describe('n: n×n shadow rays per hit.'),
      shape: z.enum(['rectangle', 'disc']).default('rectangle'),
    }),
  ])
  .describe('A point, spot or area light.');

export const sceneSchema = z
  .strictObject({
    version: z.literal(1).describe('The scene format version.'),
    name: name(),
    camera: cameraSchema.prefault({}),
    settings: settingsSchema.prefault({}),
    objects: z.array(sceneObjectSchema).max(LIMITS.objectCount[1]).default([]),
    lights: z.array(lightSchema).max(LIMITS.lightCount[1]).default([]),
  })
  .superRefine(asRefinement(idsAreUnique), alsoWhenFieldsFail)
  .superRefine(asRefinement(primaryRaysWithinLimit), alsoWhenFieldsFail)
  .meta({
    title: 'Ray Tracer Quest scene',
    description:
      'A scene file (version 1): camera, render settings, objects and lights. Two rules JSON Schema ' +
      'cannot say: ids are unique across objects and lights, the camera target differs from its ' +
      'position, and supersampling² · lensSamples² · timeSamples is at most 1024. See docs/scene-format.md.',
  });

/** A scene, or every problem with it as data (src/util/issue.ts). */
export type SceneParseResult = { ok: true; scene: Scene } | { ok: false; errors: Issue[] };

/** Checks a scene file's parsed JSON and fills in every default; lists every problem. */
export function parseScene(input: unknown): SceneParseResult {
  const result = sceneSchema.safeParse(input, { error: describeIssue });
  if (result.success) return { ok: true, scene: result.data };
  return { ok: false, errors: issuesOf(result.error.issues) };
}

/** `parseScene` for the text of a scene file; bad JSON gives one line with its place. */
export function parseSceneJson(text: string): SceneParseResult {
  // Windows editors may start a UTF-8 file with a byte-order mark, which JSON.parse refuses.
  const json = text.replace(/^\uFEFF/, '');
  let input: unknown;
  try {
    input = JSON.parse(json);
  } catch {
    return { ok: false, errors: [jsonIssue(json)] };
  }
  return parseScene(input);
}

/** True when two types accept exactly the same values. */
type SameType<A, B> = [A] extends [B] ? ([B] extends [A] ? true : false) : false;
type Assert<T extends true> = T;

/**
 * Compile-time guard that the schema above and the hand-written types in scene.ts say the
 * same thing. `mesh` is the one deliberate difference: the schema knows the asset names,
 * scene.ts keeps a string so that the tracer's MeshLibrary can be keyed by it.
 */
export type SchemaMatchesSceneTypes = [
  Assert<SameType<z.output<typeof cameraSchema>, Camera>>,
  Assert<SameType<z.output<typeof settingsSchema>, RenderSettings>>,
  Assert<SameType<z.output<typeof materialSchema>, Material>>,
  Assert<SameType<Omit<z.output<typeof sceneObjectSchema>, 'mesh'>, Omit<SceneObject, 'mesh'>>>,
  Assert<SameType<z.output<typeof lightSchema>, Light>>,
  Assert<SameType<Omit<z.output<typeof sceneSchema>, 'objects'>, Omit<Scene, 'objects'>>>,
  Assert<z.output<typeof sceneSchema> extends Scene ? true : false>,
];
