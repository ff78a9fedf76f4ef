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
