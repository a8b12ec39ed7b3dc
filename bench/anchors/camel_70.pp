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
 <point x="0.000181735" y="0.471487" z="0.414816" active="1" name="nose_tip~head_top@50"/>
 <point x="-0.036588" y="0.408101" z="0.463521" active="1" name="nose_tip~chin@50"/>
 <point x="0.032282" y="0.442811" z="0.414963" active="1" name="nose_tip~left_cheek@50"/>
 <point x="-0.0237503" y="0.452866" z="0.405881" active="1" name="nose_tip~right_cheek@50"/>
 <point x="0.000178213" y="0.483247" z="0.28457" active="1" name="head_top~nape@50"/>
 <point x="0.0217681" y="0.323796" z="0.362867" active="1" name="chin~neck_bottom@33"/>
 <point x="0.0246766" y="0.153852" z="0.299442" active="1" name="chin~neck_bottom@67"/>
 <point x="0.000177509" y="0.35806" z="0.270916" active="1" name="nape~neck_mid@50"/>
 <point x="0.00148347" y="0.24759" z="0.1824" active="1" name="neck_mid~withers@50"/>
 <point x="0.0371881" y="0.277309" z="0.285418" active="1" name="left_cheek~left_flank@25"/>
 <point x="0.0906563" y="0.194174" z="0.164382" active="1" name="left_cheek~left_flank@50"/>
 <point x="-0.0303484" y="0.277749" z="0.27802" active="1" name="right_cheek~right_flank@25"/>
 <point x="-0.0882931" y="0.159461" z="0.174599" active="1" name="right_cheek~right_flank@50"/>
 <point x="0.011791" y="0.370278" z="-0.0360135" active="1" name="withers~mid_back@50"/>
 <point x="0.000164125" y="0.350728" z="-0.234528" active="1" name="mid_back~rump@50"/>
 <point x="0.00762091" y="0.239191" z="-0.390332" active="1" name="rump~tail_base@50"/>
 <point x="0.00783223" y="0.134473" z="-0.450846" active="1" name="tail_base~tail_tip@33"/>
 <point x="0.00266122" y="0.0480496" z="-0.44907" active="1" name="tail_base~tail_tip@67"/>
 <point x="-2.67672e-005" y="0.0325429" z="0.150438" active="1" name="neck_bottom~chest@50"/>
 <point x="-0.00201036" y="0.0111862" z="-0.0193749" active="1" name="chest~belly@50"/>
 <point x="-0.00104463" y="0.0973654" z="-0.28323" active="1" name="belly~tail_base@50"/>
 <point x="0.0962859" y="0.306026" z="-0.123546" active="1" name="left_flank~mid_back@50"/>
 <point x="-0.0870935" y="0.333182" z="-0.13222" active="1" name="right_flank~mid_back@50"/>
 <point x="0.111451" y="0.0575294" z="-0.156192" active="1" name="left_flank~belly@50"/>
 <point x="-0.110246" y="0.0585748" z="-0.160234" active="1" name="right_flank~belly@50"/>
 <point x="0.123795" y="0.195071" z="-0.308357" active="1" name="left_flank~tail_base@50"/>
 <point x="-0.10884" y="0.234583" z="-0.303103" active="1" name="right_flank~tail_base@50"/>
 <point x="0.0401234" y="-0.0486646" z="0.0845432" active="1" name="neck_bottom~left_front_knee@50"/>
 <point x="-0.0313155" y="-0.0523465" z="0.0738715" active="1" name="neck_bottom~right_front_knee@50"/>
 <point x="0.125348" y="0.155001" z="0.0766271" active="1" name="withers~left_front_knee@33"/>
 <point x="0.0985935" y="-0.040602" z="0.0630005" active="1" name="withers~left_front_knee@67"/>
 <point x="-0.110744" y="0.187923" z="0.123782" active="1" name="withers~right_front_knee@33"/>
 <point x="-0.0650859" y="-0.0258589" z="0.0984276" active="1" name="withers~right_front_knee@67"/>
 <point x="0.0171796" y="0.125455" z="-0.410596" active="1" name="rump~left_hind_knee@33"/>
 <point x="0.0239757" y="-0.0475657" z="-0.429953" active="1" name="rump~left_hind_knee@67"/>
 <point x="-0.029844" y="0.149138" z="-0.417768" active="1" name="rump~right_hind_knee@33"/>
 <point x="-0.0264312" y="-0.0473995" z="-0.431352" active="1" name="rump~right_hind_knee@67"/>
 <point x="0.0302575" y="-0.387526" z="0.0515998" active="1" name="left_front_knee~left_front_foot@50"/>
 <point x="-0.036545" y="-0.386659" z="0.0518562" active="1" name="right_front_knee~right_front_foot@50"/>
 <point x="0.0384222" y="-0.368543" z="-0.423969" active="1" name="left_hind_knee~left_hind_foot@50"/>
 <point x="-0.0534309" y="-0.362374" z="-0.427063" active="1" name="right_hind_knee~right_hind_foot@50"/>
 <point x="0.0281415" y="-0.0960404" z="0.0507947" active="1" name="chest~left_front_knee@50"/>
 <point x="-0.0279816" y="-0.0962539" z="0.05245" active="1" name="chest~right_front_knee@50"/>
 <point x="0.0583575" y="0.00664989" z="-0.302881" active="1" name="belly~left_hind_knee@50"/>
 <point x="-0.0469187" y="0.0121562" z="-0.314929" active="1" name="belly~right_hind_knee@50"/>
</PickedPoints>
