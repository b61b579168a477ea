/**
 * @file   ppirayProgress.h
 * @brief  the mapper's preparation reported as VTK progress (vtkCommand::ProgressEvent)
 *
 * The mapper is a vtkAlgorithm: its progress is UpdateProgress(fraction),
 * which observers (ParaView's progress bar through the representation)
 * receive as ProgressEvent. The cell layouts report their own stages
 * (ppiray::ProgressEvents()); ProgressForwarding maps them into a part
 * [from, to] of the mapper's.
 */
#ifndef ppirayProgress_h
#define ppirayProgress_h

#include "vtkAlgorithm.h"       // for vtkAlgorithm::UpdateProgress
#include "vtkCallbackCommand.h" // for vtkCallbackCommand
#include "vtkCommand.h"         // for vtkCommand::ProgressEvent
#include "vtkNew.h"             // for vtkNew

namespace ppiray
{
/**
 * The part of a rebuild's progress that the cells' stages take (validation
 * before, field, upload and integration tables after).
 */
constexpr double CellsProgress[2] = { 0.05, 0.85 };

/** `fraction` of the preparation done, as `reporter`'s progress where it is an algorithm. */
inline void ReportProgress(vtkObject* reporter, double fraction)
{
  if (auto* algorithm = vtkAlgorithm::SafeDownCast(reporter))
  {
    algorithm->UpdateProgress(fraction);
  }
}

/**
 * While it lives, `source`'s progress f (ProgressEvent, a double*) is
 * `reporter`'s progress from + (to - from) f.
 */
class ProgressForwarding
{
public:
  ProgressForwarding(vtkObject* source, vtkObject* reporter, double from, double to)
    : Source(source)
    , Reporter(reporter)
    , From(from)
    , To(to)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* callData)
      {
        const auto& forwarding = *static_cast<ProgressForwarding*>(self);
        const double f = *static_cast<double*>(callData);
        ReportProgress(
          forwarding.Reporter, forwarding.From + (forwarding.To - forwarding.From) * f);
      });
    this->Tag = source->AddObserver(vtkCommand::ProgressEvent, this->Command);
  }
  ~ProgressForwarding() { this->Source->RemoveObserver(this->Tag); }
  ProgressForwarding(const ProgressForwarding&) = delete;
  ProgressForwarding& operator=(const ProgressForwarding&) = delete;

private:
  vtkObject* Source;
  vtkObject* Reporter;
  double From;
  double To;
  vtkNew<vtkCallbackCommand> Command;
  unsigned long Tag = 0;
};
}

#endif
