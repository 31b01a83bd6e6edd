!> The leapfrog of landyn_scheme_leapfrog with the footpads' normal contact force taken linearly
!! implicitly (a W-method / IMEX step, gear-local): the scheme of the 'imex' integrator
!! (docs/theory.md, "Stiff candidate: linearly implicit footpad contact").
!!
!! For each footpad in contact whose gear moves, with the normal force F(delta, delta_dot) of the
!! evaluation, its tangent K = dF/d(delta), C = dF/d(delta_dot) (the contact law's `tangent`) and
!! the footpad's mobility along the outward normal w = n . (footpad acceleration per newton of
!! normal footpad force, with the body's frame held: the gear's `footpad_response`, plus the body's
!! share), the new penetration rate u+ of the step solves
!!
!!   u+ = u_ex - k w dF,   dF = theta K h u+ + C (u+ - u_e)
!!
!! (u_ex the rate after the explicit velocity update, u_e the rate the evaluation was made with,
!! k the kick, h the step), i.e.
!!
!!   u+ = (u_ex + k w C u_e) / (1 + k w (theta h K + C)),
!!
!! and the force change dF (at least -F: the ground never pulls) is added, as k dF times the gear's
!! and the body's unit responses, to the velocities; the accelerations committed with the step
!! are the corrected ones (the next evaluation's velocity lead uses them). theta weighs the
!! end-of-step penetration: theta = 1 is implicit Euler (L-stable, but it adds a numerical damping
!! theta h K, a first-order error), theta = 0 the leapfrog. theta = min(1, c_theta (h omega)^2),
!! omega^2 = K w, keeps the leapfrog's second order where the footpad's oscillation is resolved
!! (h omega << 1) and is implicit Euler where it is not. A gear whose decisions (locks, sliding
!! directions) would change under the unit force, or is rigid, gets no correction. The tangential
!! friction force is left explicit.
module landyn_scheme_imex
  use landyn_kinds, only: wp, max_gears, max_gear_q
  use landyn_status, only: STAT_OK, status_t
  use landyn_kinematics, only: cross3, mv3, mtv3
  use landyn_body, only: body_t, body_point_velocity, body_point_acceleration
  use landyn_terrain, only: penetration_rate, surface_normal
  use landyn_gear_base, only: gear_eval_t
  use landyn_sim_model, only: sim_t, sim_eval_t
  use landyn_sim_state, only: max_nv, vel_layout, sim_commit_evaluation, sim_moving, sim_gather_velocities, &
                              sim_gather_accelerations
  use landyn_scheme_leapfrog, only: leapfrog_move
  implicit none
  private

  public :: imex_advance, imex_response_t, imex_responses

  real(wp), parameter :: c_theta = 0.25_wp  !! theta = min(1, c_theta (h omega)^2), omega^2 = K w [-]

  !> Each footpad's linear response to its normal force at an evaluation (imex_responses).
  type :: imex_response_t
    logical :: on(max_gears) = .false.                  !! the footpad gets the implicit correction [-]
    real(wp) :: n(3, max_gears) = 0.0_wp                !! outward surface normal, global [-]
    real(wp) :: d_l(3, max_gears) = 0.0_wp              !! footpad joint, lander frame [m]
    real(wp) :: qdd_u(max_gear_q, max_gears) = 0.0_wp   !! gear accelerations per newton [m/s^2/N, rad/s^2/N]
    real(wp) :: acc_u(3, max_gears) = 0.0_wp            !! body acceleration per newton, global [m/s^2/N]
    real(wp) :: alpha_u(3, max_gears) = 0.0_wp          !! body angular acceleration per newton, lander axes [rad/s^2/N]
    real(wp) :: w(max_gears) = 0.0_wp                   !! normal footpad acceleration per newton, 1/m_eff [1/kg]
    integer :: n_off = 0                                !! footpads in contact left explicit (decisions changed) [-]
  end type imex_response_t

contains

  !> The responses of every footpad in contact to its normal force, at the evaluation ev of the
  !! committed state (call before the evaluation is committed), in the field the evaluation was
  !! made in (ev%acc_field, ev%alpha_field) and for its step (ev%dt).
  subroutine imex_responses(sim, ev, rsp, st)
    type(sim_t), intent(in) :: sim              !! simulation (committed state of ev)
    type(sim_eval_t), intent(in) :: ev          !! evaluation of that state
    type(imex_response_t), intent(inout) :: rsp !! the responses (previous contents replaced)
    type(status_t), intent(out) :: st           !! STAT_OK, or the gear's failure with its context [-]
    type(body_t) :: body
    real(wp) :: r(3, 3), rg(3, 3), field(3), ffoot(3), dir(3), fb_u(3), mb_u(3), fb_l(3), pos(3), vel(3), a_fp(3)
    integer :: i, nq
    logical :: ok
    rsp%n_off = 0
    body = sim%model%body
    body%acc = ev%acc_field
    body%alpha = ev%alpha_field
    r = body%r
    do i = 1, sim%model%par%n_gears
      rsp%on(i) = .false.
      if (ev%delta(i) <= 0.0_wp .or. ev%gear(i)%rigid) cycle
      associate (g => sim%model%gear(i)%g)
        nq = sim%model%par%n_q(i)
        rg = sim%model%par%rot(:, :, i)
        field = mtv3(rg, mtv3(r, sim%model%par%g_vec) - body_point_acceleration(body, sim%model%par%point_a(:, i)))
        ffoot = mtv3(rg, mtv3(r, ev%fground(:, i)))
        rsp%n(:, i) = surface_normal(sim%model%par%plane(i))
        dir = mtv3(rg, mtv3(r, rsp%n(:, i)))
        call g%footpad_response(ev%gear(i), ffoot, field, dir, rsp%qdd_u(:, i), fb_u, mb_u, ok, st, ev%dt, &
                                mtv3(rg, ev%alpha_field))
        if (st%code /= STAT_OK) then
          call st%add_context('imex: gear', ev%t, i)
          return
        end if
        if (.not. ok) then
          rsp%n_off = rsp%n_off + 1
          cycle
        end if
        fb_l = mv3(rg, fb_u)
        rsp%acc_u(:, i) = mv3(r, fb_l)/body%mass
        rsp%alpha_u(:, i) = mv3(body%inv_inertia, mv3(rg, mb_u) - cross3(body%mc, fb_l))
        ! footpad acceleration per newton: the legs' relative one (linear in the rates) and the body's
        call g%footpad(pos, vel, rsp%qdd_u(1:nq, i))
        rsp%d_l(:, i) = mv3(rg, pos)
        a_fp = rsp%acc_u(:, i) + mv3(r, cross3(rsp%alpha_u(:, i), rsp%d_l(:, i) - body%mc)) + mv3(r, mv3(rg, vel))
        rsp%w(i) = dot_product(rsp%n(:, i), a_fp)
        rsp%on(i) = rsp%w(i) > 0.0_wp
      end associate
    end do
  end subroutine imex_responses

  !> One step of length h from the state evaluated in ev, with the footpads' normal contact forces
  !! linearly implicit (responses rsp from imex_responses of the same state, before this call).
  !! As leapfrog_advance otherwise; stat /= 0 leaves the simulation unusable (restore a snapshot).
  subroutine imex_advance(sim, ev, rsp, h, kick, st)
    type(sim_t), intent(inout) :: sim           !! simulation, advanced to ev%t + h
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the state at t (sim_evaluate)
    type(imex_response_t), intent(in) :: rsp    !! the footpads' responses at ev (imex_responses)
    real(wp), intent(in) :: h                   !! step [s]
    real(wp), intent(in) :: kick                !! velocity update length (variable-step leapfrog) [s]
    type(status_t), intent(out) :: st           !! STAT_OK, or the failure with its context [-]
    real(wp) :: v(max_nv), a(max_nv), df(max_gears)
    logical :: moving(max_gears), changed(max_gears)
    integer :: nv, first(max_gears), i, nq
    type(gear_eval_t) :: ge

    call sim_commit_evaluation(sim, ev)
    call sim_moving(sim, moving)
    call sim_gather_velocities(sim, v, nv)
    call sim_gather_accelerations(sim, ev, moving, a)
    v(1:nv) = v(1:nv) + a(1:nv)*kick
    call vel_layout(sim, first, nv)
    call contact_corrections(sim, ev, rsp, moving, first, h, kick, v, a, df)
    changed = rsp%on .and. moving
    ! the accelerations the step was taken with are the corrected ones (the next velocity lead)
    sim%model%body%acc = a(1:3)
    sim%model%body%alpha = a(4:6)
    do i = 1, sim%model%par%n_gears
      if (.not. changed(i)) cycle
      nq = sim%model%par%n_q(i)
      ge = ev%gear(i)
      ge%qdd(1:nq) = a(first(i):first(i) + nq - 1)
      call sim%model%gear(i)%g%commit(ge)
    end do
    call leapfrog_move(sim, ev, moving, v, h, st)
  end subroutine imex_advance

  !> The implicit normal-force change of each footpad in contact (one after the other, each with
  !! the velocities the previous ones left) and its effect on the velocities v and accelerations a.
  subroutine contact_corrections(sim, ev, rsp, moving, first, h, kick, v, a, df)
    type(sim_t), intent(in) :: sim              !! simulation (committed state of ev)
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the state
    type(imex_response_t), intent(in) :: rsp    !! the footpads' responses
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    integer, intent(in) :: first(max_gears)     !! first entry of each gear in v [-]
    real(wp), intent(in) :: h                   !! step [s]
    real(wp), intent(in) :: kick                !! velocity update length [s]
    real(wp), intent(inout) :: v(max_nv)        !! end-of-step velocities, explicit -> corrected [m/s, rad/s]
    real(wp), intent(inout) :: a(max_nv)        !! accelerations, explicit -> corrected [m/s^2, rad/s^2]
    real(wp), intent(out) :: df(max_gears)      !! normal force change of each footpad [N]
    type(body_t) :: body
    real(wp) :: pos(3), vel(3), vd(3), u_ex, u_e, u_new, k, c, kw, theta
    integer :: i, nq, j1, j2
    df = 0.0_wp
    body = sim%model%body
    do i = 1, sim%model%par%n_gears
      if (.not. (rsp%on(i) .and. moving(i))) cycle
      nq = sim%model%par%n_q(i)
      j1 = first(i)
      j2 = first(i) + nq - 1
      body%v = v(1:3)
      body%omega = v(4:6)
      call sim%model%gear(i)%g%footpad(pos, vel, v(j1:j2))
      vd = body_point_velocity(body, rsp%d_l(:, i)) + mv3(body%r, mv3(sim%model%par%rot(:, :, i), vel))
      u_ex = penetration_rate(sim%model%par%plane(i), vd)
      u_e = penetration_rate(sim%model%par%plane(i), ev%vd(:, i))
      call sim%model%par%contact%tangent(ev%delta(i), u_e, k, c, ev%trial(i)%contact)
      kw = kick*rsp%w(i)
      theta = min(1.0_wp, c_theta*h*h*max(k, 0.0_wp)*rsp%w(i))
      u_new = (u_ex + kw*c*u_e)/(1.0_wp + kw*(theta*h*k + c))
      df(i) = max(theta*k*h*u_new + c*(u_new - u_e), -ev%fn(i))
      v(1:3) = v(1:3) + kick*df(i)*rsp%acc_u(:, i)
      v(4:6) = v(4:6) + kick*df(i)*rsp%alpha_u(:, i)
      v(j1:j2) = v(j1:j2) + kick*df(i)*rsp%qdd_u(1:nq, i)
      a(1:3) = a(1:3) + df(i)*rsp%acc_u(:, i)
      a(4:6) = a(4:6) + df(i)*rsp%alpha_u(:, i)
      a(j1:j2) = a(j1:j2) + df(i)*rsp%qdd_u(1:nq, i)
    end do
  end subroutine contact_corrections

end module landyn_scheme_imex
