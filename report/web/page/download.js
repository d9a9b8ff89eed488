  // page/download.js: JSON text saved as a file (the scene, a lesson's answers).
  // JSON text downloaded as a file.
  function download(text, name) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
    link.download = name;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000); // once the download has begun
  }

