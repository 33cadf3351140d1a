#include "tool_actor.h"

#include <vtkActor.h>
#include <vtkAssembly.h>
#include <vtkCylinderSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

namespace isurface::vis {

namespace {

constexpr double kShankLengthInRadii = 8.0;

vtkSmartPointer<vtkActor> toolPart(vtkPolyDataMapper* mapper) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(0.55, 0.57, 0.6);
  p->SetSpecular(0.4);
  p->SetSpecularPower(30);
  p->SetOpacity(0.55);
  actor->PickableOff();  // a pick goes through it to the surface
  return actor;
}

}  // namespace

vtkSmartPointer<vtkAssembly> makeBallEndMill(double radius) {
  auto ball = vtkSmartPointer<vtkSphereSource>::New();
  ball->SetRadius(radius);
  ball->SetCenter(0, 0, radius);
  ball->SetThetaResolution(32);
  ball->SetPhiResolution(16);
  auto ballMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  ballMapper->SetInputConnection(ball->GetOutputPort());

  // vtkCylinderSource stands along Y about its centre: turned onto Z, from the ball's centre up.
  const double shank = kShankLengthInRadii * radius;
  auto cylinder = vtkSmartPointer<vtkCylinderSource>::New();
  cylinder->SetRadius(radius);
  cylinder->SetHeight(shank);
  cylinder->SetResolution(32);
  cylinder->CappingOn();
  auto cylinderMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  cylinderMapper->SetInputConnection(cylinder->GetOutputPort());
  vtkSmartPointer<vtkActor> shankActor = toolPart(cylinderMapper);
  shankActor->SetOrientation(90, 0, 0);
  shankActor->SetPosition(0, 0, radius + 0.5 * shank);

  auto tool = vtkSmartPointer<vtkAssembly>::New();
  tool->AddPart(toolPart(ballMapper));
  tool->AddPart(shankActor);
  tool->PickableOff();
  return tool;
}

}  // namespace isurface::vis
