#include "isurface/vis/offscreen_render.h"

#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <vtkImageData.h>

#include <chrono>
#include <functional>
#include <cstring>
#include <string_view>

#include "isurface/io/atomic_file.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/vis/osmesa_context.h"

namespace isurface::vis {

std::string pngOfRgb(const unsigned char* rgbBottomFirst, int width, int height) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::memcpy(image->GetScalarPointer(), rgbBottomFirst, static_cast<std::size_t>(width) * height * 3);
  auto png = vtkSmartPointer<vtkPNGWriter>::New();
  png->SetInputData(image);
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)), static_cast<std::size_t>(bytes->GetNumberOfValues()));
}

std::string renderOffscreen(int width, int height, const std::function<void(vtkRenderWindow*)>& draw) {
  OsMesaContext context(width, height);
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  window->SetSize(width, height);
  // Multisampling makes llvmpipe several times slower for little gain on a map.
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  auto makeCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  makeCurrent->SetClientData(&context);
  makeCurrent->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
    auto* c = static_cast<OsMesaContext*>(client);
    if (!c->isCurrent()) c->makeCurrent();
  });
  auto isCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  isCurrent->SetClientData(&context);
  isCurrent->SetCallback([](vtkObject*, unsigned long, void* client, void* answer) {
    *static_cast<bool*>(answer) = static_cast<OsMesaContext*>(client)->isCurrent();
  });
  window->AddObserver(vtkCommand::WindowMakeCurrentEvent, makeCurrent);
  window->AddObserver(vtkCommand::WindowIsCurrentEvent, isCurrent);
  window->InitializeFromCurrentContext();
  draw(window);
  window->Render();

  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->ShouldRerenderOff();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto png = vtkSmartPointer<vtkPNGWriter>::New();
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  std::string out(reinterpret_cast<const char*>(bytes->GetPointer(0)), static_cast<std::size_t>(bytes->GetNumberOfValues()));
  window->Finalize();
  return out;
}

std::string renderSceneToPngBytes(QualityScene& scene, int width, int height) {
  return renderOffscreen(width, height, [&](vtkRenderWindow* window) {
    scene.attachTo(window);
    scene.followCamera();
  });
}

double renderSceneToPng(isurface::vis::QualityScene& scene, int width, int height, const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  writeFileAtomically(path, renderSceneToPngBytes(scene, width, height));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace isurface::vis
