// Drives report.html's controls in a real browser for cli.check_html_in_chromium (appended to a copy
// of the page after its own script): the failing case's flip shows the reference in the result's
// place and back, and zoom 2 doubles the images (the case's details opened first, as a click would). What it saw goes into a pre element, id controls-check.
window.addEventListener('load', function () {
  // A case's images are in its details, closed until a click: open them as a reader would.
  document.querySelectorAll('details.case').forEach(function (details) { details.open = true; });
  var block = document.querySelector('.case-images .fail').closest('.case-images');
  var shown = block.querySelector('img.shown'), reference = block.querySelector('img.reference');
  var button = block.querySelector('button'), result = shown.src, seen = [];
  seen.push(shown.src !== reference.src ? 'result' : 'reference');
  flip(button);
  seen.push(shown.src === reference.src ? 'reference' : 'result');
  flip(button);
  seen.push(shown.src === result ? 'result' : 'reference');
  zoom(2);
  seen.push('zoom ' + shown.clientWidth / shown.naturalWidth);
  var note = document.createElement('pre');
  note.id = 'controls-check';
  note.textContent = seen.join(', ');
  document.body.appendChild(note);
});
