import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { fetchBuildFiles, listBuildFiles } from '../../app/build-files.ts';
import { fnv1a } from '../../classroom/assignment-id.ts';
import type { ScormVersion } from '../../classroom/scorm/lms-api.ts';
import { classroomStyles } from './classroom-styles.ts';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * The teacher page's SCORM downloads: the assignment as a package that a school's learning
 * platform (Moodle, Canvas, itslearning, Brightspace) imports and launches, so that each
 * pupil's completion, score and answers arrive there (docs/classroom.md, "SCORM"). The
 * package holds this build's own files (app/build-files.ts), fetched from the server the
 * page came from; the dev server and the USB-stick copy have no list of them, and the
 * buttons then say so instead of making a package that would not run.
 */
export class RtScormDownload extends LocalizedElement {
  static override properties = {
    link: { attribute: false },
    assignmentTitle: { attribute: false },
    status: { state: true },
    busy: { state: true },
  };

  static override styles = [
    classroomStyles,
    css`
      h3 {
        font-size: 1rem;
        margin: calc(var(--rt-space) * 2) 0 var(--rt-space);
      }
      .row {
        display: flex;
        flex-wrap: wrap;
        gap: 8px;
        align-items: center;
      }
    `,
  ];

  /** The student link (the assignment in its fragment), or null while none is ready. */
  declare link: string | null;
  declare assignmentTitle: string;
  declare status: string;
  declare busy: boolean;

  constructor() {
    super();
    this.link = null;
    this.assignmentTitle = '';
    this.status = '';
    this.busy = false;
  }

  private async download(version: ScormVersion): Promise<void> {
    const link = this.link;
    if (!link || this.busy) return;
    this.busy = true;
    try {
      const paths = await listBuildFiles(location.href);
      if (!paths) {
        this.status = msg('A package can only be made from the built app on a web server (not the development server, not the copy on a USB stick).');
        return;
      }
      const total = paths.length;
      const files = await fetchBuildFiles(location.href, paths, (done) => (this.status = msg(str`Collecting the app's files: ${done} of ${total}…`)));
      const { scormPackage, packageFileName } = await import('../../classroom/scorm/scorm-package.ts');
      const parameters = link.slice(link.indexOf('#'));
      const bytes = scormPackage({
        version,
        identifier: `rtq-${fnv1a(parameters).toString(16).padStart(8, '0')}`,
        title: this.assignmentTitle,
        parameters,
        files,
      });
      saveBytes(bytes, packageFileName(this.assignmentTitle, version));
      this.status = msg('The package is downloaded: upload it to your learning platform as a SCORM activity.');
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      this.status = msg(str`The package could not be made: ${reason}`);
    } finally {
      this.busy = false;
    }
  }

  override render() {
    const disabled = !this.link || this.busy;
    return html`
      <h3>${msg('For a learning platform (SCORM)')}</h3>
      <p class="muted">${msg("Moodle, Canvas, itslearning and Brightspace import a SCORM package and record each student's completion, score and answers. Choose 2004 when your platform offers it (it also records how long each answer took); 1.2 works almost everywhere.")}</p>
      <div class="row">
        <button type="button" ?disabled=${disabled} @click=${() => this.download('2004')}>${msg('SCORM 2004 package')}</button>
        <button type="button" ?disabled=${disabled} @click=${() => this.download('1.2')}>${msg('SCORM 1.2 package')}</button>
      </div>
      ${this.status ? html`<p class="muted" role="status">${this.status}</p>` : nothing}
    `;
  }
}

/** Hands bytes to the browser as a file download. */
function saveBytes(bytes: Uint8Array, fileName: string): void {
  const url = URL.createObjectURL(new Blob([bytes as BlobPart], { type: 'application/zip' }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.click();
  setTimeout(() => URL.revokeObjectURL(url), 0);
}

customElements.define('rt-scorm-download', RtScormDownload);

declare global {
  interface HTMLElementTagNameMap {
    'rt-scorm-download': RtScormDownload;
  }
}
