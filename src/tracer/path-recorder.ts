import type { Vector3 } from 'three';
import type { Color } from '../scene/scene.ts';

/**
 * What happened at a path's vertex (path-tracing spec §3): where it started, how it
 * scattered, or why it ended. `absorbed` is this tracer's addition: a mirror direction that
 * roughness spread below the surface, or a surface that reflects nothing.
 */
export type PathEvent =
  'camera' | 'diffuse' | 'mirror' | 'glass-reflect' | 'glass-refract' | 'emitter' | 'escaped' | 'roulette-stop' | 'max-depth' | 'absorbed';

/** A light-sampling (next-event) ray from a diffuse vertex to a point on a light. */
export interface LightSampleRay {
  lightId: string;
  target: Color;
  visible: boolean;
  /** What it added to the pixel: throughput × BRDF × cosθ × incoming / density. */
  added: Color;
}

export interface PathVertex {
  event: PathEvent;
  point: Color;
  /** The shading normal, turned toward the incoming ray; null at the camera and for a ray that escaped. */
  normal: Color | null;
  objectId: string | null;
  lightId: string | null;
  /** The direction sampled here, and its density (per steradian; null for a mirror or glass's single direction). */
  direction: Color | null;
  pdf: number | null;
  /** The path's throughput after this vertex: what a unit of light arriving along the next segment adds to the pixel. */
  throughput: Color;
  lightSamples: LightSampleRay[];
}

/** One sample's path: its vertices and what it added to the pixel (the image's pixel is the mean of these). */
export interface RecordedPath {
  vertices: PathVertex[];
  contribution: Color;
}

/** Records the paths of a pixel while the path integrator traces them; rendering passes null. */
export class PathRecorder {
  readonly paths: RecordedPath[] = [];
  private current: RecordedPath | null = null;
  /**
   * Light samples taken at the surface the path has just hit: the integrator samples the
   * lights before it records that surface's vertex, so they wait here for it.
   */
  private pending: LightSampleRay[] = [];

  start(origin: Vector3, direction: Vector3): void {
    this.current = { vertices: [], contribution: [0, 0, 0] };
    this.paths.push(this.current);
    this.vertex('camera', origin, null, null, null, direction, null, [1, 1, 1]);
  }

  vertex(
    event: PathEvent,
    point: Vector3,
    normal: Vector3 | null,
    objectId: string | null,
    lightId: string | null,
    direction: Vector3 | null,
    pdf: number | null,
    throughput: Color,
  ): void {
    this.current!.vertices.push({
      event,
      point: point.toArray(),
      normal: normal?.toArray() ?? null,
      objectId,
      lightId,
      direction: direction?.toArray() ?? null,
      pdf,
      throughput,
      lightSamples: this.pending,
    });
    this.pending = [];
  }

  /** A light sample taken at the surface whose vertex is recorded next. */
  lightSample(lightId: string, target: Vector3, visible: boolean, added: Color): void {
    this.pending.push({ lightId, target: target.toArray(), visible, added });
  }

  end(contribution: Vector3): void {
    this.current!.contribution = contribution.toArray();
    this.current = null;
  }
}
