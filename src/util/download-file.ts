/** Hands text to the browser as a file download; nothing leaves the computer. */
export function downloadText(text: string, fileName: string, type: string): void {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.click();
  // The click has started the download; the address is no longer needed after this task.
  setTimeout(() => URL.revokeObjectURL(url), 0);
}

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
