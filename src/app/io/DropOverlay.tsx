/** The full-window hint shown while a file is dragged over the page. */
export function DropOverlay() {
  return (
    <div className="kf-drop" data-testid="drop-overlay" aria-hidden="true">
      <div className="kf-drop__card">
        <strong>Drop to open</strong>
        <span>a .kleinflow.json graph, a Flower graph, or a PNG exported by Kleinflow</span>
      </div>
    </div>
  );
}
