import { msg, str } from '@lit/localize';
import type { PathVertexRow } from '../../../debugger/path-steps.ts';
import type { BounceSampling } from '../../../scene/scene.ts';
import { localNumbers } from '../../../i18n/number-format.ts';
import { colorText } from './debug-numbers.ts';

const number = localNumbers({ minimumFractionDigits: 3, maximumFractionDigits: 3 });

/** What happened at a path's vertex, in a sentence (docs/path-tracing.md, "The estimator"). */
export function vertexText(row: PathVertexRow, sampling: BounceSampling): string {
  const where = row.objectId ?? '';
  switch (row.event) {
    case 'camera':
      return msg('The camera ray leaves through a random point of the pixel. The throughput starts at (1, 1, 1).');
    case 'diffuse': {
      const how = sampling === 'cosine' ? msg('drawn with density cosθ/π (cosine-weighted)') : msg('drawn uniformly over the hemisphere, density 1/(2π)');
      return msg(
        str`Hits ${where}: a diffuse bounce. The new direction is ${how}; the throughput is multiplied by f·cosθ/pdf, with f = albedo/π, and divided by the chance of picking the diffuse part when the surface also has a mirror part.`,
      );
    }
    case 'mirror':
      return msg(str`Hits ${where}: the mirror part reflects. The throughput is multiplied by ks over the chance of picking the mirror.`);
    case 'glass-reflect':
      return msg(str`Hits ${where}, glass: reflected, with the Fresnel chance F. The throughput stays the same (F/F).`);
    case 'glass-refract':
      return msg(str`Hits ${where}, glass: refracted, with chance 1 − F. The throughput stays the same.`);
    case 'emitter':
      return msg(
        str`Reaches the area light ${row.lightId ?? ''}: its lit side adds throughput × Le, unless the light sample of a diffuse bounce just before counted it already. The path ends.`,
      );
    case 'escaped':
      return msg('Leaves the scene: the background adds throughput × its radiance. The path ends.');
    case 'roulette-stop':
      return msg('Russian roulette stops the path here: nothing more is added.');
    case 'max-depth':
      return msg(str`Hits ${where} after the last bounce that Max bounces allows: the path ends.`);
    case 'absorbed':
      return msg(str`Ends at ${where}: the sampled direction went into the surface, or the surface reflects nothing.`);
  }
}

/** The event's short name, for the table. */
export function eventName(event: PathVertexRow['event']): string {
  switch (event) {
    case 'camera':
      return msg('camera');
    case 'diffuse':
      return msg('diffuse bounce');
    case 'mirror':
      return msg('mirror');
    case 'glass-reflect':
      return msg('glass, reflected');
    case 'glass-refract':
      return msg('glass, refracted');
    case 'emitter':
      return msg('area light');
    case 'escaped':
      return msg('escaped');
    case 'roulette-stop':
      return msg('stopped by roulette');
    case 'max-depth':
      return msg('max bounces reached');
    case 'absorbed':
      return msg('absorbed');
  }
}

/** Russian roulette's weight at a vertex, or ''. */
export function survivalText(row: PathVertexRow): string {
  return row.survival === null
    ? ''
    : msg(str`Russian roulette: the path goes on with chance ${number.format(row.survival)}, so its throughput is divided by it.`);
}

/** One light sample of a vertex. */
export function lightSampleText(sample: PathVertexRow['lightSamples'][number]): string {
  return sample.visible
    ? msg(str`Light sample: the shadow ray to ${sample.lightId} reaches it and adds ${colorText(sample.added)}.`)
    : msg(str`Light sample: the shadow ray to ${sample.lightId} is blocked and adds nothing.`);
}

export { number as pathNumber };
