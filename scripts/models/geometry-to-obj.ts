import type { BufferAttribute, BufferGeometry, InterleavedBufferAttribute } from 'three';

/**
 * Formats a number with at most 5 decimals (0.01 mm at the models' 1 m scale), without
 * trailing zeros, and never as "-0", so that equal positions get equal text.
 */
function formatNumber(value: number): string {
  return String(Number(value.toFixed(5)) + 0);
}

/** Numbers each distinct line of text once, in first-seen order (OBJ indices start at 1). */
class NumberedLines {
  private readonly numbers = new Map<string, number>();

  numberOf(text: string): number {
    let number = this.numbers.get(text);
    if (number === undefined) {
      number = this.numbers.size + 1;
      this.numbers.set(text, number);
    }
    return number;
  }

  get count(): number {
    return this.numbers.size;
  }

  lines(keyword: string): string[] {
    return [...this.numbers.keys()].map((text) => `${keyword} ${text}`);
  }
}

/**
 * Writes a geometry's triangles as Wavefront OBJ text (`v`, `vn`, `f v//vn`).
 *
 * Positions and normals are shared by their written text, which welds the seams three's
 * geometries leave for their texture coordinates. Triangles that then have two equal
 * corners are dropped: they are the zero-area slivers where a sphere, capsule or lathe
 * pinches to a point, and they would leave the surface with edges used only once.
 *
 * @param comments - Header lines, written as `# …` before the triangle count.
 */
export function geometryToObj(geometry: BufferGeometry, comments: string[]): string {
  const position = geometry.getAttribute('position');
  const normal = geometry.getAttribute('normal');
  const index = geometry.getIndex();
  const cornerCount = index ? index.count : position.count;
  const positions = new NumberedLines();
  const normals = new NumberedLines();
  const faces: string[] = [];

  const vectorText = (attribute: BufferAttribute | InterleavedBufferAttribute, vertex: number): string =>
    [attribute.getX(vertex), attribute.getY(vertex), attribute.getZ(vertex)].map(formatNumber).join(' ');

  for (let first = 0; first < cornerCount; first += 3) {
    const vertices = [first, first + 1, first + 2].map((corner) => (index ? index.getX(corner) : corner));
    const places = vertices.map((vertex) => vectorText(position, vertex));
    const [a, b, c] = places;
    if (a === b || b === c || c === a) continue;
    const corners = vertices.map((vertex, k) => `${positions.numberOf(places[k])}//${normals.numberOf(vectorText(normal, vertex))}`);
    faces.push(`f ${corners.join(' ')}`);
  }

  return [
    ...comments.map((comment) => `# ${comment}`),
    `# ${faces.length} triangles, ${positions.count} positions, ${normals.count} normals.`,
    ...positions.lines('v'),
    ...normals.lines('vn'),
    ...faces,
    '',
  ].join('\n');
}
