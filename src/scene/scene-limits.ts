/**
 * The ranges the scene schema accepts, as [lowest, highest] (both allowed). The spec fixes
 * the ones that protect the browser (pixels, imageSize, samples, supersampling, maxDepth,
 * object count, spot angle); the rest are our choices, explained in docs/scene-format.md
 * under "Choices we made". UI sliders may offer a narrower range, never a wider one.
 */
export const LIMITS = {
  /** Any x, y or z of a position, target or rotation (metres or degrees): far beyond any
   * lesson, and it keeps the intersection maths clear of overflow and precision loss. */
  coordinate: [-10_000, 10_000],
  /** Vertical field of view in degrees; 0 and 180 have no image. */
  fov: [1, 179],
  /** The visualized screen: every pixel draws a ray tree, so more than 64 per side floods the view. */
  pixels: [1, 64],
  /** Eye to drawn screen, metres; only for drawing, but 0 would draw the screen inside the eye. */
  screenDistance: [0.01, 100],
  maxDepth: [0, 10],
  supersampling: [1, 8],
  /** Full render size per side; 4096² is already 16 M primary rays. */
  imageSize: [1, 4096],
  objectCount: [0, 256],
  /** Each light adds shadow rays at every hit; an area light up to 100 of them. */
  lightCount: [0, 32],
  /** Per axis. Positive only: a negative scale turns a plane or mesh inside out without
   * looking different, which makes its lighting and refraction puzzling. Rotate instead. */
  scale: [0.001, 1000],
  /** Colour channels, linear. */
  channel: [0, 1],
  /** Material ka, kd, ks and a light's ambient, diffuse, specular: fractions, as in VRT. */
  coefficient: [0, 1],
  /** Phong exponent n; past 10000 the highlight is smaller than a pixel. */
  shininess: [0, 10_000],
  /** η: 1 is air; 4 is past diamond (2.42) and germanium-like optics, enough to exaggerate. */
  refractiveIndex: [1, 4],
  /** Light intensity I; 100 leaves room to light far objects with distance attenuation on. */
  intensity: [0, 100],
  /** Full cone angle of a spot light in degrees. */
  spotAngle: [1, 170],
  /** p in cos(α)^p; at 64 the cone is already a narrow pencil, as on the lab's slider. */
  angleAttenuation: [0, 64],
  /** An area light's width and depth in metres. */
  areaSize: [0.01, 100],
  /** n: n×n shadow rays per area light and hit. */
  areaSamples: [1, 10],
  /** A lens radius in metres: past 0.5 m only the focal plane would be recognisable. */
  aperture: [0, 0.5],
  /** Distance of the plane in focus, metres (distribution-effects §1). */
  focusDistance: [0.05, 100],
  /** n: n×n lens points per pixel sample. */
  lensSamples: [1, 8],
  /** ρ, the spread of glossy rays around the mirror (or refracted) direction. */
  roughness: [0, 1],
  /** m: m×m glossy rays per hit; they multiply at every bounce. */
  glossySamples: [1, 8],
  /** Each component of an object's movement during the shutter, metres. */
  velocity: [-10, 10],
  /** k: shutter times per pixel sample. */
  timeSamples: [1, 16],
  /** s²·n²·k, the primary rays of one pixel (distribution-effects §1). */
  primaryRaysPerPixel: [1, 1024],
  /** N: random paths per pixel in path mode (path-tracing spec §1); 65,536 converges any lesson's scene. */
  pathSamples: [1, 65_536],
  /** Stops of exposure in path mode: the picture times 2^exposure before display. */
  exposure: [-10, 10],
  /** Characters in an id (goals and ray trees quote it) and in a display name. */
  idLength: [1, 64],
  nameLength: [0, 100],
} as const satisfies Record<string, readonly [number, number]>;
