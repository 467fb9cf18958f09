// The live 3D view of a step: the scene's objects, the ray tree as lines in the window's
// colours, the hit points, the camera glyph and other extras (doc/web-data.md), drawn by
// vtk.js with its trackball interactor (drag: rotate, wheel: zoom, Shift-drag: pan).
// Rays are grouped into one actor per (depth, colour, width), so the depth slider only
// switches actors on and off.
// Only WebGL (vtk.js's OpenGL profiles) is bundled, not WebGPU: a third less to load.
import '@kitware/vtk.js/Rendering/OpenGL/Profiles/Geometry';
import '@kitware/vtk.js/Rendering/OpenGL/Profiles/Glyph';
import vtkInteractorStyleTrackballCamera from '@kitware/vtk.js/Interaction/Style/InteractorStyleTrackballCamera';
import vtkOpenGLRenderWindow from '@kitware/vtk.js/Rendering/OpenGL/RenderWindow';
import vtkRenderWindow from '@kitware/vtk.js/Rendering/Core/RenderWindow';
import vtkRenderWindowInteractor from '@kitware/vtk.js/Rendering/Core/RenderWindowInteractor';
import vtkRenderer from '@kitware/vtk.js/Rendering/Core/Renderer';
import vtkActor from '@kitware/vtk.js/Rendering/Core/Actor';
import vtkMapper from '@kitware/vtk.js/Rendering/Core/Mapper';
import vtkGlyph3DMapper from '@kitware/vtk.js/Rendering/Core/Glyph3DMapper';
import vtkPolyData from '@kitware/vtk.js/Common/DataModel/PolyData';
import vtkDataArray from '@kitware/vtk.js/Common/Core/DataArray';
import vtkSphereSource from '@kitware/vtk.js/Filters/Sources/SphereSource';

/// Decodes base64 little-endian data into a typed array (Float32Array, Uint32Array...).
function decode(base64, ArrayType) {
  if (!base64) return new ArrayType(0);
  const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
  return new ArrayType(bytes.buffer, 0, bytes.byteLength / ArrayType.BYTES_PER_ELEMENT);
}

/// A vtk.js actor for one Mesh of the contract (points + polys/lines/verts).
function meshActor(mesh) {
  const polyData = vtkPolyData.newInstance();
  polyData.getPoints().setData(decode(mesh.points, Float32Array), 3);
  if (mesh.polys) polyData.getPolys().setData(decode(mesh.polys, Uint32Array));
  if (mesh.strips) polyData.getStrips().setData(decode(mesh.strips, Uint32Array));
  if (mesh.lines) polyData.getLines().setData(decode(mesh.lines, Uint32Array));
  if (mesh.verts) polyData.getVerts().setData(decode(mesh.verts, Uint32Array));
  const mapper = vtkMapper.newInstance();
  mapper.setInputData(polyData);
  if (mesh.cellColors) {
    const colors = decode(mesh.cellColors, Uint8Array);
    polyData.getCellData().setScalars(
      vtkDataArray.newInstance({ name: 'colors', numberOfComponents: 3, values: colors }));
    mapper.setColorModeToDirectScalars();
    mapper.setScalarModeToUseCellData();
  } else {
    mapper.setScalarVisibility(false);
  }
  const actor = vtkActor.newInstance();
  actor.setMapper(mapper);
  const property = actor.getProperty();
  property.setColor(...mesh.color);
  property.setOpacity(mesh.opacity ?? 1);
  property.setLineWidth(mesh.lineWidth || 1);
  property.setPointSize(mesh.pointSize || 1);
  property.setLighting(mesh.lit !== false);
  // One-sided walls (the window culls their back faces, so a camera outside the box sees in).
  property.setBackfaceCulling(Boolean(mesh.backfaceCulling));
  return actor;
}

/// One actor per group of rays drawn alike; returns [{ depth, actor }].
function rayActors(rays) {
  const groups = new Map();
  for (const ray of rays) {
    if (ray.drawn === false) continue;
    const key = `${ray.depth}|${ray.color.join(',')}|${ray.width}`;
    if (!groups.has(key)) groups.set(key, { depth: ray.depth, color: ray.color, width: ray.width, rays: [] });
    groups.get(key).rays.push(ray);
  }
  return [...groups.values()].map((group) => {
    const points = new Float32Array(group.rays.length * 6);
    const lines = new Uint32Array(group.rays.length * 3);
    group.rays.forEach((ray, i) => {
      points.set(ray.origin, 6 * i);
      points.set(ray.end, 6 * i + 3);
      lines.set([2, 2 * i, 2 * i + 1], 3 * i);
    });
    const polyData = vtkPolyData.newInstance();
    polyData.getPoints().setData(points, 3);
    polyData.getLines().setData(lines);
    const mapper = vtkMapper.newInstance();
    mapper.setInputData(polyData);
    const actor = vtkActor.newInstance();
    actor.setMapper(mapper);
    actor.getProperty().setColor(...group.color);
    actor.getProperty().setLineWidth(group.width || 2);
    actor.getProperty().setLighting(false);
    return { depth: group.depth, actor };
  });
}

/// Small spheres at the hit points (one glyph mapper, one actor per depth of the ray hit).
function hitActors(hits, rays, radius) {
  const depthOf = new Map(rays.map((ray) => [ray.id, ray.depth]));
  const byDepth = new Map();
  for (const hit of hits) {
    const depth = depthOf.get(hit.ray) ?? 0;
    if (!byDepth.has(depth)) byDepth.set(depth, []);
    byDepth.get(depth).push(hit.point);
  }
  return [...byDepth.entries()].map(([depth, points]) => {
    const polyData = vtkPolyData.newInstance();
    polyData.getPoints().setData(Float32Array.from(points.flat()), 3);
    const mapper = vtkGlyph3DMapper.newInstance({ scaling: false });
    mapper.setInputData(polyData, 0);
    mapper.setInputConnection(
      vtkSphereSource.newInstance({ radius, thetaResolution: 12, phiResolution: 12 }).getOutputPort(), 1);
    const actor = vtkActor.newInstance();
    actor.setMapper(mapper);
    actor.getProperty().setColor(1, 1, 1);
    return { depth, actor };
  });
}

/// A WebGL render window filling `container`, with the trackball interactor, resized with
/// the container; returns { renderer, renderWindow, delete() }.
function renderWindowIn(container, background) {
  const renderWindow = vtkRenderWindow.newInstance();
  const renderer = vtkRenderer.newInstance({ background });
  renderWindow.addRenderer(renderer);
  const glWindow = vtkOpenGLRenderWindow.newInstance();
  glWindow.setContainer(container);
  renderWindow.addView(glWindow);
  const interactor = vtkRenderWindowInteractor.newInstance();
  interactor.setView(glWindow);
  interactor.initialize();
  interactor.bindEvents(container);
  interactor.setInteractorStyle(vtkInteractorStyleTrackballCamera.newInstance());
  const resize = () => {
    const { width, height } = container.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    glWindow.setSize(Math.max(1, Math.floor(width * ratio)), Math.max(1, Math.floor(height * ratio)));
    renderWindow.render();
  };
  const observer = new ResizeObserver(resize);
  observer.observe(container);
  resize();
  return {
    renderer,
    renderWindow,
    delete() {
      observer.disconnect();
      interactor.unbindEvents();
      interactor.delete();
      glWindow.delete();
      renderWindow.delete();
    },
  };
}

/// Builds the view inside `container`; returns { showDepth(d), resetCamera(), rotate(a, e),
/// zoom(f), delete() }.
export function createView(container, view3d) {
  const { renderer, renderWindow, delete: release } = renderWindowIn(container, view3d.background);

  for (const mesh of view3d.objects) renderer.addActor(meshActor(mesh));
  for (const mesh of view3d.extras) renderer.addActor(meshActor(mesh));
  // Hit points about 1% of the view's height across, whether the step is a close-up or not.
  const { position, focalPoint, viewAngle } = view3d.camera;
  const distance = Math.hypot(...position.map((p, i) => p - focalPoint[i]));
  const radius = 0.012 * distance * Math.tan((viewAngle * Math.PI) / 360);
  const layered = [...rayActors(view3d.rays), ...hitActors(view3d.hits, view3d.rays, radius)];
  for (const { actor } of layered) renderer.addActor(actor);

  const camera = renderer.getActiveCamera();
  function resetCamera() {
    camera.setPosition(...view3d.camera.position);
    camera.setFocalPoint(...view3d.camera.focalPoint);
    camera.setViewUp(...view3d.camera.viewUp);
    camera.setViewAngle(view3d.camera.viewAngle);
    renderer.resetCameraClippingRange();
    renderWindow.render();
  }
  resetCamera();

  return {
    showDepth(depth) {
      for (const { depth: d, actor } of layered) actor.setVisibility(d <= depth);
      renderWindow.render();
    },
    resetCamera,
    rotate(azimuth, elevation) {
      camera.azimuth(azimuth);
      camera.elevation(elevation);
      camera.orthogonalizeViewUp();
      renderer.resetCameraClippingRange();
      renderWindow.render();
    },
    zoom(factor) {
      camera.dolly(factor);
      renderer.resetCameraClippingRange();
      renderWindow.render();
    },
    delete: release,
  };
}

/// Whether this browser can draw WebGL at all.
export function webglAvailable() {
  try {
    const canvas = document.createElement('canvas');
    return Boolean(canvas.getContext('webgl2') || canvas.getContext('webgl'));
  } catch (error) {
    return false;
  }
}
