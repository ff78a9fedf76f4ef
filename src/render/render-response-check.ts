/**
 * A worker's message is checked before the pool acts on it: a worker with a bug (or a
 * message a browser extension posted) once sent `null`, which threw a TypeError in the page.
 * A message that is not a well-formed RenderResponse (workers/protocol.ts) is dropped, with
 * the reason for the log.
 */
import type { FailedRequest, RenderResponse } from '../../workers/protocol.ts';
import { isRecord } from '../util/is-record.ts';

export type CheckedResponse = { ok: true; response: RenderResponse } | { ok: false; reason: string };

/** Error texts are shown to the learner: a worker's are cut to a readable length. */
const MESSAGE_MAX = 500;

const isId = (value: unknown): value is number => Number.isSafeInteger(value) && (value as number) >= 0;
const isTime = (value: unknown): value is number => typeof value === 'number' && Number.isFinite(value) && value >= 0;
const RAY_KINDS = ['primary', 'shadow', 'reflect', 'refract'] as const;

export function checkResponse(data: unknown): CheckedResponse {
  if (!isRecord(data)) return refuse(`not an object but ${data === null ? 'null' : typeof data}`);
  switch (data.type) {
    case 'scene-ready':
      if (!isId(data.sceneId) || !isTime(data.ms)) return refuse('a scene-ready without a scene id and time');
      return accept({ type: 'scene-ready', sceneId: data.sceneId, ms: data.ms });
    case 'tile-done': {
      const { jobId, tileId, rgb, stats, ms } = data;
      if (!isId(jobId) || !isId(tileId) || !isTime(ms)) return refuse('a tile-done without job and tile ids and a time');
      const floats = rgb instanceof Float32Array || rgb instanceof Float64Array;
      if (!floats || !(rgb.buffer instanceof ArrayBuffer)) return refuse('a tile-done whose pixels are not a Float32Array or Float64Array');
      if (!isRecord(stats) || !RAY_KINDS.every((kind) => isTime(stats[kind]))) return refuse('a tile-done without ray counts');
      const counts = { primary: stats.primary as number, shadow: stats.shadow as number, reflect: stats.reflect as number, refract: stats.refract as number };
      return accept({ type: 'tile-done', jobId, tileId, rgb: rgb as Float32Array<ArrayBuffer> | Float64Array<ArrayBuffer>, stats: counts, ms });
    }
    case 'pixel-traced':
      if (!isId(data.requestId) || !isRayTree(data.trace)) {
        return refuse('a pixel-traced without a request id and a ray tree');
      }
      return accept(data as unknown as RenderResponse);
    case 'pixels-traced':
      if (!isId(data.requestId) || !Array.isArray(data.traces) || !data.traces.every(isRayTree)) {
        return refuse('a pixels-traced without a request id and ray trees');
      }
      return accept(data as unknown as RenderResponse);
    case 'paths-traced':
      if (!isId(data.requestId) || !isRecord(data.paths) || !Array.isArray(data.paths.paths) || !Array.isArray(data.paths.contributions)) {
        return refuse('a paths-traced without a request id and paths');
      }
      return accept(data as unknown as RenderResponse);
    case 'error': {
      const failed = checkFailed(data.failed);
      if (!failed || typeof data.message !== 'string') return refuse('an error without the failed request and a message');
      const message = data.message.length > MESSAGE_MAX ? `${data.message.slice(0, MESSAGE_MAX)}…` : data.message;
      return accept({ type: 'error', failed, message });
    }
    default:
      return refuse(`an unknown type ${typeof data.type === 'string' ? JSON.stringify(data.type.slice(0, 40)) : String(data.type)}`);
  }
}

function checkFailed(failed: unknown): FailedRequest | null {
  if (!isRecord(failed)) return null;
  if (failed.type === 'load-scene' && isId(failed.sceneId)) return { type: 'load-scene', sceneId: failed.sceneId };
  if (failed.type === 'render-tile' && isId(failed.jobId) && isId(failed.tileId)) return { type: 'render-tile', jobId: failed.jobId, tileId: failed.tileId };
  if ((failed.type === 'trace-pixel' || failed.type === 'trace-pixels' || failed.type === 'trace-paths') && isId(failed.requestId))
    return { type: failed.type, requestId: failed.requestId };
  return null;
}

/** The outline of a PixelTrace: its pixel, colour and roots (the trees' insides are the tracer's). */
function isRayTree(trace: unknown): boolean {
  return isRecord(trace) && Array.isArray(trace.rays) && Array.isArray(trace.pixel) && Array.isArray(trace.color);
}

function accept(response: RenderResponse): CheckedResponse {
  return { ok: true, response };
}

function refuse(reason: string): CheckedResponse {
  return { ok: false, reason };
}
