#include "GuideDialog.h"
#include "MathText.h"

#include <QDialogButtonBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "viewpipe/math_text.hpp"

namespace viewpipe::gui {
namespace {

// The stage symbols are written as the stage's symbol (SH_per), set as math
// below, as the stage list sets them, so that a student can find each one here.
QString guideHtml()
{
    return GuideDialog::tr(R"(
<h2>ViewPipe: the 3D viewing pipeline, one matrix at a time</h2>
<p>ViewPipe shows how a camera turns a 3D scene into a picture: the
normalizing transformation of Foley &amp; van Dam (<i>N<sub>per</sub></i> for
perspective, <i>N<sub>par</sub></i> for parallel projection) and the OpenGL
forms (gluLookAt with gluPerspective, glFrustum or glOrtho), applied one
matrix after another.</p>

<h3>The two views</h3>
<p><b>World view</b> (left): the scene's objects and the viewing set-up in
world coordinates: the world axes x, y, z; the view reference coordinates (VRC)
with their axes u, v, n at the view reference point (VRP), or for an OpenGL
camera the eye's axes s, u, -f; the center of projection (PRP, or the eye);
the window on the view plane and its center CW; the direction of projection
(DOP, from the PRP to CW); the view volume with its front (F) and back (B)
planes, or near and far; and the projectors through the window's corners. The
legend in the top-right corner names each color, for what this scene shows.
Drag with the left button to turn the view, with the middle button (or Shift
and the left button) to pan; the wheel or the right button zooms. <b><kbd>R</kbd></b>
resets the view.</p>
<p><b>Projected view</b> (right): what the camera sees, the picture inside the
window. For a perspective view it also draws the vanishing points and the lines
meeting there. Its legend is in the bottom-right corner. <b>P</b> shows or
hides it.</p>

<h3>The stepper</h3>
<p>The <b>Stages</b> panel lists the matrices in order; stage 0 is the world.
Choosing a stage applies every matrix up to it to everything in the world view,
so you watch the scene and the set-up move together. <b>Left</b> and
<b>Right</b> (or Previous and Next, or <b>Page Up</b> and <b>Page Down</b>)
step back and forth, <b>Play</b> runs through all stages and <b>Stop</b> halts.
<b>F5</b> presents: the two views alone, full screen, in large black on white;
a presenter's clicker steps, <b>B</b> blacks the screen out and <b>Esc</b>
leaves. The caption says which matrix was
applied last. After the last stage the canonical view volume appears: the
normalized volume every later step (clipping, projection) works in.
A matrix that makes w vary (the perspective ones) is followed by the divide
by w: what lies behind the eye has no image and is not drawn, and what lies
between the eye and the near plane would be thrown far out, so it is cut
away just before the near plane.</p>

<h3>The stages of N<sub>per</sub> (perspective)</h3>
<ol>
<li><b>T(-VRP)</b>: translate the view reference point to the origin.</li>
<li><b>R</b>: rotate the VRC onto the world axes: u to x, v to y, n to z.</li>
<li><b>T(-PRP)</b>: translate the center of projection (PRP) to the origin.</li>
<li><b>SH_per</b>: shear so that the center line of the view volume (the DOP)
becomes the z axis.</li>
<li><b>S_per</b>: scale so that the view volume becomes the canonical
perspective volume: x = z, y = z and x = -z, y = -z, from the front plane to
z = -1.</li>
</ol>
<p>With the Divide effect a further stage, <b>M</b>, maps the canonical
perspective volume onto the canonical parallel volume; the divide by w
follows.</p>

<h3>The stages of N<sub>par</sub> (parallel)</h3>
<ol>
<li><b>T(-VRP)</b> and <b>R</b>, as above.</li>
<li><b>SH_par</b>: shear so that the direction of projection becomes parallel
to the z axis (nothing to do for an orthographic view).</li>
<li><b>T_par</b>: translate the center of the front face of the view volume to
the origin.</li>
<li><b>S_par</b>: scale so that the view volume becomes the canonical parallel
volume: x and y from -1 to 1, z from 0 to -1.</li>
</ol>

<h3>The OpenGL forms</h3>
<p>An OpenGL camera starts with the view transformation of gluLookAt:
<b>T(-eye)</b> translates the eye to the origin and <b>R_eye</b> rotates so
that the view direction becomes &minus;<i>z</i> (rows <i>s</i>, <i>u</i>, &minus;<i>f</i>). The projection follows:</p>
<ul>
<li>gluPerspective: <b>S_fovy</b> scales <i>x</i> and <i>y</i> so that the field of view
becomes 90&deg;, then <b>P_depth</b>, the perspective matrix: <i>w</i> = &minus;<i>z</i>, and
near to far mapped to &minus;1 to 1 after the divide.</li>
<li>glFrustum: <b>SH_frustum</b> shears the frustum's center line onto the &minus;<i>z</i>
axis, <b>S_frustum</b> scales its sides to <i>x</i> = &plusmn;<i>z</i>, <i>y</i> = &plusmn;<i>z</i>, then
<b>P_depth</b>.</li>
<li>glOrtho: <b>T_ortho</b> moves the center of the view box to the origin and
<b>S_ortho</b> scales the box to the cube [&minus;1, 1]&sup3;, flipping <i>z</i>.</li>
</ul>
<p>With the Divide effect an OpenGL camera gains the stage <b>divide</b>:
clip coordinates become normalized device coordinates (NDC).</p>

<h3>Direct3D, Vulkan, Metal and WebGPU</h3>
<p>The Parameters panel's API, Handedness and Depth choices (the scene's
"api", "handedness" and "depth") give the same camera another API's
conventions, as extra stages around OpenGL's projection:</p>
<ul>
<li><b>Z_flip</b>, after <b>R_eye</b> for a left-handed camera (XMMatrixLookAtLH,
glm::lookAtLH: the eye looks down +<i>z</i>): <i>z</i> is mirrored so that the projection's
stages apply.</li>
<li><b>NDC_direct3d</b>, <b>NDC_vulkan</b>, <b>NDC_metal</b>,
<b>NDC_webgpu</b>: OpenGL's clip coordinates to the API's, depth from 0 (near)
to 1 (far), and for Vulkan <i>y</i>&prime; = &minus;<i>y</i>; with reversed depth near goes to 1 and far
to 0, and the stage is <b>NDC_direct3d_reversed</b>, <b>NDC_vulkan_reversed</b>,
<b>NDC_metal_reversed</b> or <b>NDC_webgpu_reversed</b> (OpenGL's own reversed
depth: <b>NDC_reversed</b>).</li>
</ul>
<p>The products are the APIs' own matrices (glm, DirectXMath). The presets
under Graphics APIs show one view in each.</p>

<h3>The panels</h3>
<ul>
<li><b>Matrices</b>: the current stage's matrix, symbolic (with the formulas
of its entries) and in numbers, and the cumulative matrix, the product of all
stages so far, with the entries this stage changed highlighted. Below it, the
traced vertex.</li>
<li><b>Parameters</b>: every number of the camera (VRP, VPN, VUP, PRP, the
window, F and B; or eye, center, up and the projection). Edit one and the
pipeline is rebuilt; a value the mathematics refuses is explained beside its
field and the last valid scene stays.</li>
<li><b>The camera as code</b>, below the parameters: the camera in legacy
OpenGL, glm, DirectXMath, three.js or wgpu-matrix. Drag a marked number, or Tab to it and press Up or
Down, or double-click it to type; paste a call (Ctrl+V over the code) to set
the camera; Copy copies the code.</li>
<li><b>Accuracy</b>: how exact the pipeline is in float, double, long double,
double-double, float128 and MPFR, against an MPFR reference of 256 bits, and
how long each takes: a table and two charts of error against time.</li>
<li><b>Depth</b>: with the depth buffer effect, the smallest change of distance
the buffer can tell apart, against the distance, for the scene's format and the
usual others, and the faces that z-fight.</li>
</ul>

<h3>Effects</h3>
<p>The <b>Effects</b> menu adds what happens after the normalizing
transformation, each change one undoable edit: <b>Clip</b> cuts edges at the
view volume and ghosts what is clipped away; <b>Divide</b> appends the divide
as a stage; <b>Back-face culling</b> ghosts the faces turned away;
<b>Depth buffer</b> (16, 24 or 32 bits fixed point, 32-bit float, reversed Z)
colors the faces in bands of equal stored depth and marks the faces it cannot
order (z-fighting), labelled in the world view and ringed in the projected
view; <b>Raster</b> shows which pixels each object covers.</p>

<h3>Tracing a vertex</h3>
<p>Click a vertex of an object in the world view: the Matrices panel lists its
homogeneous coordinates (x, y, z, w) after every stage, the current one in
bold, and says whether it ends inside the canonical volume.</p>

<h3>Files, presets and export</h3>
<p><b>File &#9656; Open</b> reads a scene (JSON), <b>Save</b> and <b>Save
As</b> write it; <b>Presets</b> holds example scenes, among them the classical
projections (one-, two- and three-point perspective, isometric, cavalier,
cabinet...). <b>Import Mesh</b> adds an OBJ, PLY or STL model; you can also
drop files on the window. <b>View &#9656; Classical Projection</b> sets up one
of the classical views of the scene's objects. <b>Export Stages</b> writes
every stage as PNG, SVG or PDF pictures, the matrices as LaTeX and JSON, and on
request an MP4 animation, into a folder of your pictures. <b>Edit</b> copies the
current matrix as LaTeX or the world view as an image.</p>

<h3>Lessons</h3>
<p><b>Lesson &#9656; Built-in Lessons</b> or <b>Open Lesson</b> (Ctrl+L) opens a
lesson in the Lesson panel: each step shows its scene, stage and view with a
caption. A step with a question waits at the stage before the one it asks
about, with the stage names, the matrices and the caption hidden: type the
coordinates or the entry (fractions such as -2/21 are fine), click a choice,
or put the stages in order, then <b>Check</b> (Enter). The answer comes with
the transition to the stage and its explanation; <b>Show Answer</b> reveals it
without one. <b>Save My Answers</b> writes your answers and whether each was
right. Page Down goes on (a question first shows its answer), Page Up back;
in present mode (F5) the lesson stays beside the views. <b>Edit the lesson</b>
in the panel adds the current view as a step, reorders steps and edits the
title, the caption and the question (as JSON, checked as the file is);
<b>Lesson &#9656; Save Lesson</b> writes it.</p>

<h3>Themes and text size</h3>
<p><b>View &#9656; Dark Theme</b> suits the screen, <b>Light Theme</b> slides
and print; exports choose their own theme. <b>Larger Text</b> and <b>Smaller
Text</b> change the size of all text, in the views too.</p>

<h3>Keys</h3>
<table cellspacing="0" cellpadding="3">
<tr><td><b>Left</b> / <b>Right</b></td><td>previous / next stage</td></tr>
<tr><td><b>Page Up</b> / <b>Page Down</b></td><td>previous / next lesson step (or stage without a lesson)</td></tr>
<tr><td><b>F5</b></td><td>present; then Space and Backspace step, B blacks out, Esc leaves</td></tr>
<tr><td><b>Ctrl+L</b></td><td>open a lesson</td></tr>
<tr><td><b>Ctrl+Z</b></td><td>undo</td></tr>
<tr><td><b>Ctrl+Shift+Z</b> or <b>Ctrl+Y</b></td><td>redo</td></tr>
<tr><td><b>P</b></td><td>show or hide the projected view</td></tr>
<tr><td><b><kbd>R</kbd></b></td><td>reset the world view's camera</td></tr>
<tr><td><b>Ctrl+K</b></td><td>classical projection</td></tr>
<tr><td><b>Ctrl+E</b></td><td>export stages</td></tr>
<tr><td><b>Ctrl++</b> / <b>Ctrl+-</b></td><td>larger / smaller text</td></tr>
<tr><td><b>Ctrl+O</b>, <b>Ctrl+S</b>, <b>Ctrl+Shift+S</b></td><td>open, save, save as</td></tr>
<tr><td><b>Ctrl+Shift+C</b></td><td>copy the matrix as LaTeX</td></tr>
<tr><td><b>Ctrl+Shift+I</b></td><td>copy the world view as an image</td></tr>
<tr><td><b>F1</b></td><td>this guide</td></tr>
</table>
)");
}

// The guide with each bold stage symbol (<b>SH_per</b>) set as the stage list sets it, as math.
QString guideWithSymbols()
{
    QString html = guideHtml();
    // A symbol has a subscript (SH_per), a negated point (T(-VRP)), or is one of the one-letter stages.
    static const QRegularExpression symbol(R"(<b>([A-Z][A-Za-z]*(?:_[a-z0-9_]+|\(-[A-Za-z]+\))|R|M)</b>)");
    for (QRegularExpressionMatch m = symbol.match(html); m.hasMatch(); m = symbol.match(html, m.capturedStart() + 1)) {
        const QString math = "<b>" + mathHtml("$" + symbolMath(m.captured(1).toStdString()) + "$") + "</b>";
        html.replace(m.capturedStart(), m.capturedLength(), math);
    }
    return html;
}

} // namespace

GuideDialog::GuideDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName("guideDialog");
    setWindowTitle(tr("ViewPipe Guide"));
    setModal(false);
    auto* layout = new QVBoxLayout(this);
    browser_ = new QTextBrowser;
    browser_->setObjectName("guideText");
    browser_->setHtml(guideWithSymbols());
    layout->addWidget(browser_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->button(QDialogButtonBox::Close)->setToolTip(tr("Close the guide"));
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    layout->addWidget(buttons);
    resize(720, 760);
}

GuideDialog* GuideDialog::showFor(QWidget* parent)
{
    auto* guide = parent->findChild<GuideDialog*>(QString(), Qt::FindDirectChildrenOnly);
    if (!guide)
        guide = new GuideDialog(parent);
    guide->show();
    guide->raise();
    guide->activateWindow();
    return guide;
}

} // namespace viewpipe::gui
