// Drives report.html's controls in a real browser for cli.check_html_in_chromium (appended to a copy
// of the page after its own script): the failing case's flip shows the reference in the result's
// place and back, and zoom 2 doubles the images. What it saw goes into a pre element, id controls-check.
window.addEventListener('load', function () {
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
