/**
 * `ray-tracer-quest-<participant>-<assignment>-<YYYY-MM-DD>-<HHhMM>-local.<extension>`: a
 * class's files sort by participant code in a teacher's Downloads folder and do not
 * overwrite each other. The time is the pupil's clock (what the teacher also sees on the
 * classroom wall), and the name says so: an unmarked UTC time read as local is an hour or
 * two off in the Netherlands. The exact moment, in UTC, is inside the file (`exportedAt`).
 */
export function exportFileName(participant: string | null, assignment: string | null, at: Date, extension: string): string {
  const two = (value: number) => String(value).padStart(2, '0');
  const date = `${at.getFullYear()}-${two(at.getMonth() + 1)}-${two(at.getDate())}`;
  const time = `${two(at.getHours())}h${two(at.getMinutes())}`;
  const parts = ['ray-tracer-quest', fileNamePart(participant ?? '', 32), fileNamePart(assignment ?? '', 30), date, time, 'local'];
  return parts.filter((part) => part !== '').join('-') + `.${extension}`;
}

/** ASCII letters, digits and single dashes only: safe on every file system and in every mail program. */
function fileNamePart(text: string, length: number): string {
  return text
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .replace(/[^A-Za-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, length)
    .replace(/-+$/, '');
}
