document.querySelectorAll('.viewer').forEach(function (v) {
  var frames = JSON.parse(v.dataset.frames), i = 0, timer = null;
  var img = v.querySelector('img'), counter = v.querySelector('.counter');
  function show(k) {
    i = (k + frames.length) % frames.length;
    img.src = frames[i];
    counter.textContent = 'frame ' + (i + 1) + ' / ' + frames.length;
  }
  v.querySelector('.prev').onclick = function () { show(i - 1); };
  v.querySelector('.next').onclick = function () { show(i + 1); };
  v.querySelector('.play').onclick = function () {
    if (timer) { clearInterval(timer); timer = null; this.textContent = 'play'; }
    else { timer = setInterval(function () { show(i + 1); }, 1200); this.textContent = 'pause'; }
  };
  show(0);
});
