/**
 * `ray-tracer-quest-<participant>-<date>.<extension>`: one learner's files sort together
 * and a class's files do not overwrite each other in a teacher's Downloads folder.
 */
export function exportFileName(participant: string | null, exportedAt: string, extension: string): string {
  const who = (participant ?? '')
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .replace(/[^A-Za-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 40);
  const when = exportedAt.slice(0, 19).replace(/[:T]/g, '-');
  return ['ray-tracer-quest', who, when].filter((part) => part !== '').join('-') + `.${extension}`;
}
