/**
 * Durations and times as ISO 8601 text, as xAPI wants them.
 *
 * A duration is written in hours, minutes and seconds only (`PT1H2M3.5S`): days and months
 * have no fixed length, and xAPI (§4.2.7) keeps 0.01 s precision, so the seconds are rounded
 * to hundredths. Zero is `PT0S`.
 */
export function isoDuration(ms: number): string {
  if (!Number.isFinite(ms) || ms < 0) throw new RangeError(`a duration must be a number of at least 0 ms, got ${ms}`);
  const hundredths = Math.round(ms / 10);
  const hours = Math.floor(hundredths / 360_000);
  const minutes = Math.floor((hundredths % 360_000) / 6_000);
  const seconds = (hundredths % 6_000) / 100;
  let text = 'PT';
  if (hours > 0) text += `${hours}H`;
  if (minutes > 0) text += `${minutes}M`;
  if (seconds > 0 || text === 'PT') text += `${seconds}S`;
  return text;
}

/** The wall-clock time of an event log time `t` (ms since `startedAt`), as ISO 8601 UTC. */
export function isoAt(startedAt: string, t: number): string {
  return new Date(Date.parse(startedAt) + t).toISOString();
}
