/** An inspector row that chooses one file ("Choose picture…", "Choose video…"): label, then the browser's picker. */
export function FileChoice({
  label,
  accept,
  onFile,
}: {
  readonly label: string;
  readonly accept: string;
  readonly onFile: (file: File | undefined) => void;
}) {
  return (
    <label className="kf-field">
      <span className="kf-field__label">{label}…</span>
      <input type="file" accept={accept} aria-label={label} onChange={(e) => onFile(e.target.files?.[0])} />
    </label>
  );
}
