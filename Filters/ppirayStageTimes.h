/**
 * @file   ppirayStageTimes.h
 * @brief  wall milliseconds of the named stages of a computation, in order
 *
 * The preparation of a frame (geometry key, validation, split, adjacency,
 * boundary, field, upload ...) reported stage by stage: each stage is timed
 * by Laps (from the last lap to this one); a stage timed twice adds up. Laps can also report
 * progress (ProgressEvents()).
 */
#ifndef ppirayStageTimes_h
#define ppirayStageTimes_h

#include "vtkCommand.h" // for vtkCommand::ProgressEvent
#include "vtkObject.h"  // for vtkObject::InvokeEvent

#include <chrono>     // for std::chrono::steady_clock
#include <functional> // for std::function
#include <string>     // for std::string
#include <utility>    // for std::move
#include <vector>     // for std::vector

namespace ppiray
{
class StageTimes
{
public:
  struct Stage
  {
    std::string Name;
    double Milliseconds;
  };

  /**
   * Consecutive stages: End(name) closes the one begun at the last End(),
   * then calls `onLap` (if any) with the number of stages ended so far.
   */
  class Laps
  {
  public:
    explicit Laps(StageTimes& times, std::function<void(int)> onLap = {})
      : Times(times)
      , OnLap(std::move(onLap))
      , Start(std::chrono::steady_clock::now())
    {
    }
    void End(const std::string& name)
    {
      const auto now = std::chrono::steady_clock::now();
      this->Times.Add(name, std::chrono::duration<double, std::milli>(now - this->Start).count());
      this->Start = now;
      if (this->OnLap)
      {
        this->OnLap(++this->Ended);
      }
    }

  private:
    StageTimes& Times;
    std::function<void(int)> OnLap;
    int Ended = 0;
    std::chrono::steady_clock::time_point Start;
  };

  /** `milliseconds` more for stage `name` (appended if new). */
  void Add(const std::string& name, double milliseconds)
  {
    for (Stage& stage : this->Stages)
    {
      if (stage.Name == name)
      {
        stage.Milliseconds += milliseconds;
        return;
      }
    }
    this->Stages.push_back({ name, milliseconds });
  }
  /** Every stage of `other`, after these. */
  void Add(const StageTimes& other)
  {
    for (const Stage& stage : other.Stages)
    {
      this->Add(stage.Name, stage.Milliseconds);
    }
  }
  void Clear() { this->Stages.clear(); }
  const std::vector<Stage>& Get() const { return this->Stages; }

private:
  std::vector<Stage> Stages;
};

/**
 * A Laps callback: `object` invokes vtkCommand::ProgressEvent with the
 * fraction done (a double*, laps / `stages`), as VTK's algorithms do.
 */
inline std::function<void(int)> ProgressEvents(vtkObject* object, int stages)
{
  return [object, stages](int laps)
  {
    double fraction = static_cast<double>(laps) / stages;
    object->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  };
}
}

#endif
