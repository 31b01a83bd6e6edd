!> Plain-text summary table printed when a run ends.
module landyn_report
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_simulation, only: sim_result_t
  implicit none
  private

  public :: write_summary_table

contains

  !> Writes the run summary (crush lengths in Table 3's layout, margins, loads, energy) to a unit.
  subroutine write_summary_table(u, inp, res)
    integer, intent(in) :: u                    !! formatted output unit
    type(landyn_input_t), intent(in) :: inp     !! resolved input
    type(sim_result_t), intent(in) :: res       !! results
    integer :: i, k, meas
    write (u, '(a)') ''
    write (u, '(a)') 'LANDYN summary: '//trim(inp%simulation%title)
    write (u, '(a,f8.4,a,i0,a,a)') '  end time ', res%t_final, ' s after ', res%n_steps, ' steps: ', trim(res%end_reason)
    if (res%integrator == 'adaptive') write (u, '(a,i0,a,i0,a,i0,a,es9.2,a,es9.2,a)') '  adaptive steps: ', &
      res%n_rejected, ' rejected, ', res%n_events, ' at located events, ', res%n_evaluations, ' force evaluations; dt ', &
      res%dt_smallest, ' .. ', res%dt_largest, ' s'
    if (res%n_forced > 0) write (u, '(a,i0,a)') '  adaptive steps: ', res%n_forced, &
      ' discontinuities crossed in steps of event_resolution (local error estimate above the tolerance)'
    write (u, '(a)') ''
    write (u, '(a)') '  meas gear strut            crush [mm]  (+) [mm]  (-) [mm]  margin [mm]  peak force [kN]  switches'
    meas = 0
    do i = 1, res%n_gears
      do k = 1, res%n_struts(i)
        meas = meas + 1
        write (u, '(2x,i4,1x,i4,1x,a15,f13.1,2f10.1,f13.1,f17.1,i10,a)') meas, i, res%strut_names(k, i), &
          1000.0_wp*res%crush_net(k, i), 1000.0_wp*res%crush_pos(k, i), 1000.0_wp*res%crush_neg(k, i), &
          1000.0_wp*res%stroke_margin(k, i), 1.0e-3_wp*res%peak_strut_force(k, i), res%mode_switches(k, i), &
          merge(' BOTTOMED OUT', '             ', res%bottomed(k, i) == 1)
      end do
    end do
    write (u, '(a)') '  (crush: final net length, primary shortening and secondary lengthening +; (+), (-): lengths'
    write (u, '(a)') '   crushed toward each sense; margin: stroke left before the strut bottoms out; peak force: over every'
    write (u, '(a)') '   time step; switches: changes of the crush mode, locked <-> crushing + <-> crushing -)'
    write (u, '(a)') ''
    write (u, '(a)') '  footpad  peak penetration [mm]  slide [m]  peak normal force [kN]'
    do i = 1, res%n_gears
      write (u, '(2x,i7,f23.2,f11.3,f24.1)') i, 1000.0_wp*res%peak_penetration(i), res%slide_distance(i), &
        1.0e-3_wp*res%peak_normal_force(i)
    end do
    write (u, '(a)') ''
    write (u, '(a)') '  interface loads, lander axes: peak |force| [kN] (t [s]) at the hard points a, b, c and the footpad d'
    write (u, '(a)') '     gear             a                  b                  c                  d'
    do i = 1, res%n_gears
      write (u, '(2x,i7,4(f11.1,a,f6.4,a))') i, (1.0e-3_wp*res%load_peaks%value(4, k, i), ' (', &
        res%load_peaks%time(4, k, i), ')', k = 1, 4)
    end do
    write (u, '(a)') '  (per component, with the simultaneous loads: /summary/peak_joint_load, landyn-export --tables)'
    if (maxval(res%peak_normal_force) > 1.05_wp*maxval(res%load_peaks%value(4, 4, :))) then
      write (u, '(a)') '  (the ground normal force peaks above the force at d in short stiff-contact spikes: d carries the'
      write (u, '(a)') '   ground force less the footpad''s own inertia, which takes most of such a spike)'
    end if
    write (u, '(a)') ''
    write (u, '(a,f8.3,a,f8.4,a)') '  peak overload at the mass centre ', res%peak_overload, ' g at t = ', &
      res%t_peak_overload, ' s'
    write (u, '(a,3f9.3,a)') '  final attitude (yaw, pitch, roll) ', res%final_euler, ' deg'
    write (u, '(a,f8.3,a,f8.3,a,a)') '  tilt: final ', res%final_tilt, ' deg, largest ', res%max_tilt, ' deg; ', &
      merge('TIPPED OVER     ', 'did not tip over', res%tipped_over)
    write (u, '(a,es11.4,a,f8.4,a)') '  energy: input ', res%energy_input, ' J, audit residual ', &
      100.0_wp*res%energy_residual, ' %'
    write (u, '(a,es10.3,a,es10.3,a)') '  constraint violation after correction ', res%max_violation, &
      ' m (drift per step before correction ', res%max_drift, ' m)'
    write (u, '(a,f8.2,a)') '  wall time ', res%wall_time, ' s'
  end subroutine write_summary_table

end module landyn_report
