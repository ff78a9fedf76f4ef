/**
 * zlib deflate and inflate of bytes with the platform's CompressionStream, for the links
 * that carry a scene or an assignment in the address. Inflating stops past a limit: a
 * link of a few hundred kilobytes can unpack to hundreds of megabytes (a "zip bomb").
 */

/** Thrown by `inflate` when the unpacked bytes pass its limit; `limit` says how many were allowed. */
export class InflatedTooLarge extends Error {
  constructor(readonly limit: number) {
    super(`it unpacks to more than ${limit / 1024} kB`);
  }
}

export async function deflate(bytes: Uint8Array): Promise<Uint8Array> {
  return new Uint8Array(await new Response(new Blob([bytes as BlobPart]).stream().pipeThrough(new CompressionStream('deflate'))).arrayBuffer());
}

/** The unpacked bytes; throws InflatedTooLarge past `limit` bytes, or a TypeError for damaged data. */
export async function inflate(bytes: Uint8Array, limit: number): Promise<Uint8Array> {
  const reader = new Blob([bytes as BlobPart]).stream().pipeThrough(new DecompressionStream('deflate')).getReader();
  const chunks: Uint8Array[] = [];
  let length = 0;
  for (let next = await reader.read(); !next.done; next = await reader.read()) {
    length += next.value.length;
    if (length > limit) {
      await reader.cancel();
      throw new InflatedTooLarge(limit);
    }
    chunks.push(next.value);
  }
  const joined = new Uint8Array(length);
  let offset = 0;
  for (const chunk of chunks) {
    joined.set(chunk, offset);
    offset += chunk.length;
  }
  return joined;
}
