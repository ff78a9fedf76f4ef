/**
 * The scene file (spec/scene-and-tracer.md §1): one plain, serializable object that the
 * view, the tracer and the quest engine all read. Units are metres, angles degrees,
 * colours linear RGB in 0..1. Defaults live in `scene-defaults.ts`; validation in
 * `scene-schema.ts` (which is checked against these types at compile time).
 */

import type { LocalizedText } from '../util/localized-text.ts';

export type Vec3 = [number, number, number];
export type Color = [number, number, number];

/** The ray tracer's camera and its small screen of pixels (the rays that are visualized). */
export interface Camera {
  position: Vec3;
  /** The point the camera looks at; `up` is +Y. */
  target: Vec3;
  /** Vertical field of view in degrees. */
  fov: number;
  /** Columns × rows of the visualized screen (1..64 per side; the lab offers 1..16). */
  pixels: [number, number];
  /** Distance from the eye to the drawn screen, in metres (only for drawing). */
  screenDistance: number;
  /** Lens radius in metres; 0 is a pinhole, where everything is sharp (distribution-effects §1). */
  aperture: number;
  /**
   * Distance of the plane in focus along the view direction, in metres. Left out, it is
   * the distance from `position` to `target`: the target is in focus.
   */
  focusDistance?: number;
  /** n: n×n points on the lens per pixel sample (ignored while aperture is 0). */
  lensSamples: number;
}

/** Where the s×s sub-pixel samples go: a regular grid (default), jittered cells or uniform random. */
export type SamplePattern = 'grid' | 'jittered' | 'random';

/**
 * Where the k shutter times of a pixel sample go (motion blur): the same evenly spaced
 * moments for every pixel, one random moment in each of k equal intervals (the default),
 * or k uniform random moments. The pixel's three patterns, in time.
 */
export type TimePattern = 'grid' | 'jittered' | 'random';

/**
 * How the image's colours c become its 8-bit values (src/tracer/quantize.ts, docs/tracer.md):
 * 'none' writes round(255·c) and lets the screen read it as its own value (no gamma, as the
 * Virtual Ray Tracer); 'linear' stores the light c in 8 equal-light steps and shows that light;
 * 'srgb' stores the light sRGB-encoded, as image files do, and shows that light.
 */
export type ImageEncoding = 'none' | 'linear' | 'srgb';

export interface RenderSettings {
  shadows: boolean;
  /** Deepest reflection/refraction recursion; primary rays are depth 0. */
  maxDepth: number;
  background: Color;
  /** s: s×s samples per pixel. */
  supersampling: number;
  samplePattern: SamplePattern;
  /** Width × height of the full rendered image. */
  imageSize: [number, number];
  /** Ordered (Bayer) dithering before 8-bit quantization; off by default. */
  dithering: boolean;
  /** How colours become 8-bit values; 'none' by default. */
  encoding: ImageEncoding;
  /** A switch per light type (the VRT ray tracer panel's toggles). */
  lightTypes: { point: boolean; spot: boolean; area: boolean };
  /** k: times in the open shutter per pixel sample (motion blur). */
  timeSamples: number;
  timePattern: TimePattern;
  /** Which estimator renders the scene: Whitted's recursive tracer, or a path tracer (docs/path-tracing.md). */
  integrator: Integrator;
  /** N: random paths per pixel (path mode). */
  pathSamples: number;
  /** Where in the pixel each path starts (path mode): stratified points, or independent random ones. */
  pixelSampling: PixelSampling;
  /** How a diffuse bounce picks its direction (path mode). */
  bounceSampling: BounceSampling;
  /** Next-event estimation: at each diffuse vertex, a shadow ray to a point on each light (path mode). */
  lightSampling: boolean;
  /** End paths at random, survivors weighted up, as well as at maxDepth (path mode). */
  russianRoulette: boolean;
  /** Stops: the picture times 2^exposure before display (path mode). */
  exposure: number;
}

export type Integrator = 'whitted' | 'path';
export type PixelSampling = 'stratified' | 'independent';
export type BounceSampling = 'cosine' | 'uniform';

export interface Material {
  color: Color;
  ambient: number;
  diffuse: number;
  specular: number;
  shininess: number;
  transparent: boolean;
  refractiveIndex: number;
  /** Spread of reflected (and refracted) rays; 0 is a perfect mirror or clear glass. */
  roughness: number;
  /** m: m×m reflected (refracted) rays per hit when roughness > 0. */
  glossySamples: number;
}

export type ShapeKind = 'sphere' | 'box' | 'cylinder' | 'plane' | 'mesh';

export interface SceneObject {
  /** Unique in the scene; ray trees and goals refer to objects by id. */
  id: string;
  /** A friendly name for the UI, in one language or per language; defaults to the id. */
  name?: LocalizedText;
  shape: ShapeKind;
  /** The model from assets/models when `shape` is "mesh". */
  mesh?: string;
  position: Vec3;
  /** Euler angles XYZ in degrees. */
  rotation: Vec3;
  scale: Vec3;
  /** How far the object moves while the shutter is open, in metres (motion blur). */
  velocity: Vec3;
  material: Material;
}

interface LightCommon {
  id: string;
  name?: LocalizedText;
  position: Vec3;
  color: Color;
  intensity: number;
  ambient: number;
  diffuse: number;
  specular: number;
  /** 1 / (0.04 + 0.1·d + 0.06·d²) when on, for every light type. */
  distanceAttenuation: boolean;
}

export interface PointLight extends LightCommon {
  type: 'point';
}

/** Emits along its local −Y (a ceiling light by default). */
export interface SpotLight extends LightCommon {
  type: 'spot';
  rotation: Vec3;
  /** Full cone angle in degrees, 1..170. */
  spotAngle: number;
  /** p in cos(α)^p. */
  angleAttenuation: number;
}

/** Lies in its local XZ plane, lit face toward local −Y, back face black. */
export interface AreaLight extends LightCommon {
  type: 'area';
  rotation: Vec3;
  /** Width (local X) × depth (local Z) in metres; a disc uses them as its diameters. */
  size: [number, number];
  /** n: n×n jittered samples. */
  samples: number;
  angleAttenuation: number;
  shape: 'rectangle' | 'disc';
}

export type Light = PointLight | SpotLight | AreaLight;
export type LightType = Light['type'];

export interface Scene {
  version: 1;
  /** Shown in the UI and in exported files. */
  name?: LocalizedText;
  camera: Camera;
  settings: RenderSettings;
  objects: SceneObject[];
  lights: Light[];
}
