<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="camel.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0.000183144" y="0.443985" z="0.475434" active="1" name="nose_tip"/>
 <point x="-0.000380376" y="0.380167" z="0.450009" active="1" name="chin"/>
 <point x="0.00617689" y="0.488161" z="0.360296" active="1" name="head_top"/>
 <point x="0.0587604" y="0.428398" z="0.33025" active="1" name="left_cheek"/>
 <point x="-0.0582821" y="0.427221" z="0.337821" active="1" name="right_cheek"/>
 <point x="0.00129469" y="0.418966" z="0.259746" active="1" name="nape"/>
 <point x="0.0105139" y="0.311769" z="0.274483" active="1" name="neck_mid"/>
 <point x="0.000175396" y="0.0723768" z="0.187257" active="1" name="neck_bottom"/>
 <point x="0.013807" y="0.340585" z="0.0757241" active="1" name="withers"/>
 <point x="0.0133984" y="0.430696" z="-0.137991" active="1" name="mid_back"/>
 <point x="0.000161308" y="0.276098" z="-0.354548" active="1" name="rump"/>
 <point x="0.013061" y="0.196927" z="-0.422609" active="1" name="tail_base"/>
 <point x="0.00015849" y="-0.0153929" z="-0.448388" active="1" name="tail_tip"/>
 <point x="0.000173283" y="0.00296165" z="0.0938751" active="1" name="chest"/>
 <point x="0.000166943" y="4.7547e-005" z="-0.142967" active="1" name="belly"/>
 <point x="0.14997" y="0.168575" z="-0.139894" active="1" name="left_flank"/>
 <point x="-0.149905" y="0.167961" z="-0.139966" active="1" name="right_flank"/>
 <point x="0.0229064" y="-0.23661" z="0.0446072" active="1" name="left_front_knee"/>
 <point x="-0.0220689" y="-0.237642" z="0.0446319" active="1" name="right_front_knee"/>
 <point x="0.0380623" y="-0.214954" z="-0.440902" active="1" name="left_hind_knee"/>
 <point x="-0.0363893" y="-0.21496" z="-0.440579" active="1" name="right_hind_knee"/>
 <point x="0.0567831" y="-0.486178" z="0.140589" active="1" name="left_front_foot"/>
 <point x="-0.0564352" y="-0.486178" z="0.140592" active="1" name="right_front_foot"/>
 <point x="0.070314" y="-0.486178" z="-0.325506" active="1" name="left_hind_foot"/>
 <point x="-0.0699892" y="-0.486178" z="-0.325502" active="1" name="right_hind_foot"/>
</PickedPoints>
