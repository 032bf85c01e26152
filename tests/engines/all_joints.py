"""One MJCF with every joint type MuJoCo has, shared by the state-map and MuJoCo frame tests."""

# free root, hinge with ref and an offset anchor, ball, a body with three joints (hinge with ref,
# slide with ref, hinge on a tilted axis: a Pinocchio composite), a slide with ref, a welded child.
ALL_JOINTS_MJCF = """
<mujoco model="all_joints">
  <compiler angle="radian"/>
  <worldbody>
    <body name="base" pos="0 0 1">
      <freejoint name="root"/>
      <inertial pos="0.1 0 0" mass="2" diaginertia="0.1 0.2 0.25"/>
      <body name="b1" pos="0.3 0 0" quat="0.9 0.1 0.2 0.3">
        <joint name="hinge1" type="hinge" axis="0 1 0" pos="0.05 0 0" ref="0.3" armature="0.1"/>
        <inertial pos="0 0.1 0" mass="1" fullinertia="0.1 0.2 0.25 0.01 0.02 0.03"/>
        <body name="b2" pos="0 0.3 0">
          <joint name="ball1" type="ball" armature="0.05"/>
          <inertial pos="0 0.1 0.02" mass="1.3" diaginertia="0.1 0.2 0.25"/>
          <body name="b3" pos="0 0.3 0">
            <joint name="c_hinge" type="hinge" axis="1 0 0" ref="0.2"/>
            <joint name="c_slide" type="slide" axis="0 0 1" ref="0.1" armature="0.2"/>
            <joint name="c_tilted" type="hinge" axis="0 1 1"/>
            <inertial pos="0 0.1 0" mass="1" diaginertia="0.1 0.2 0.25"/>
            <body name="welded" pos="0 0 0.2" euler="0.1 0.2 0.3">
              <inertial pos="0 0.1 0" mass="0.5" fullinertia="0.01 0.02 0.025 0.001 0 0"/>
            </body>
            <body name="b4" pos="0.2 0 0">
              <joint name="slide1" type="slide" axis="1 1 0" ref="-0.4"/>
              <inertial pos="0.05 0 0" mass="0.7" diaginertia="0.01 0.02 0.03"/>
            </body>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
